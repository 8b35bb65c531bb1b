package studio.server.scene.compiling;

import studio.engine.texture.MipMap;
import studio.server.system.MemoryBudget;

/**
 * Images already decoded into mip-maps, by content (an asset's SHA-256, as {@link MeshCache} keys
 * meshes): the live view sends the whole scene on every edit, and an image is decoded from sRGB once,
 * not per edit. Bounded: least recently used first out, each entry holding its share of the service's
 * {@link MemoryBudget} while it is kept; an image the budget cannot cover is not kept. Mip-maps are
 * immutable, so renders share them.
 */
public final class TextureCache {

    private final LruEntries.Bound bound;
    private final LruEntries<String, MipMap> kept;

    /** @param maxBytes at most this many bytes of mip-maps kept */
    public TextureCache(long maxBytes, MemoryBudget memory) {
        bound = new LruEntries.Bound(maxBytes, memory);
        kept = bound.newMap();
    }

    /** Keeps nothing (the command line reads each image once). */
    public static TextureCache none() {
        return new TextureCache(0, MemoryBudget.unlimited());
    }

    /** The key of an asset's entry: the hex SHA-256 its id carries; null in a cache that keeps nothing. */
    String keyOfAsset(String assetId) {
        return bound.keepsAny() ? assetId.substring(assetId.indexOf('-') + 1) : null;
    }

    synchronized MipMap get(String key) {
        return key != null ? kept.get(key) : null;
    }

    synchronized void keep(String key, MipMap image) {
        if (key != null) {
            kept.keep(key, image, image.bytes(), image.bytes());
        }
    }

    /** Bytes kept now. */
    synchronized long bytes() {
        return bound.size();
    }
}

package studio.server.scene.compiling;

import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;

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

    private record Entry(MipMap image, MemoryBudget.Reservation memory) {
    }

    private final long maxBytes;
    private final MemoryBudget memory;
    private final Map<String, Entry> kept = new LinkedHashMap<>(16, 0.75f, true);
    private long bytes;

    /** @param maxBytes at most this many bytes of mip-maps kept */
    public TextureCache(long maxBytes, MemoryBudget memory) {
        this.maxBytes = maxBytes;
        this.memory = memory;
    }

    /** Keeps nothing (the command line reads each image once). */
    public static TextureCache none() {
        return new TextureCache(0, MemoryBudget.unlimited());
    }

    /** The key of an asset's entry: the hex SHA-256 its id carries; null in a cache that keeps nothing. */
    String keyOfAsset(String assetId) {
        return maxBytes > 0 ? assetId.substring(assetId.indexOf('-') + 1) : null;
    }

    synchronized MipMap get(String key) {
        Entry entry = key != null ? kept.get(key) : null;
        return entry != null ? entry.image() : null;
    }

    synchronized void keep(String key, MipMap image) {
        long size = image.bytes();
        if (key == null || size > maxBytes) {
            return;
        }
        while (bytes + size > maxBytes && evictOldest()) {
            // evicting
        }
        MemoryBudget.Reservation reservation;
        while ((reservation = memory.tryReserve(size)) == null) {
            if (!evictOldest()) {
                return;
            }
        }
        bytes += size;
        release(kept.put(key, new Entry(image, reservation)));
    }

    /** Bytes kept now. */
    synchronized long bytes() {
        return bytes;
    }

    private boolean evictOldest() {
        Iterator<Entry> oldest = kept.values().iterator();
        if (!oldest.hasNext()) {
            return false;
        }
        release(oldest.next());
        oldest.remove();
        return true;
    }

    private void release(Entry entry) {
        if (entry != null) {
            bytes -= entry.image().bytes();
            entry.memory().close();
        }
    }
}

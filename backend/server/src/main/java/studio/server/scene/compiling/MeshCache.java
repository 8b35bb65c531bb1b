package studio.server.scene.compiling;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;

import studio.engine.geometry.TriangleMesh;
import studio.engine.math.Vec3;
import studio.engine.mesh.MeshData;
import studio.server.scene.gltf.GltfModel;
import studio.server.system.MemoryBudget;

/**
 * Meshes and glTF models already read, and meshes built, by content: the OBJ text's (or the model
 * file's) SHA-256 and, for a built mesh (its triangles placed in the world with their bounding volume
 * hierarchy; a model's part is keyed by its file's digest and its index), its placement. The live view
 * sends the whole scene on every edit; with this, moving a light or another object reuses an
 * unchanged mesh as it is, and moving the mesh reuses its parsed OBJ and its tree (only the tree's
 * boxes are fitted to the moved triangles, {@link TriangleMesh#movedTo}). A digest, not the text's hash
 * code, so that nobody can make two different meshes share an entry.
 *
 * <p>Bounded: the least recently used entries go first, and every entry holds its share of the
 * service's {@link MemoryBudget} ({@value #BYTES_PER_TRIANGLE} bytes a triangle) while it is kept;
 * when the budget cannot cover a mesh, it is not kept. Meshes are immutable once built, so renders
 * may share them.
 */
public final class MeshCache {

    /**
     * Built meshes of fewer triangles are not kept: building one takes well under a millisecond, and
     * every placement would be an entry of its own (the live view reads a mesh's other fields with a
     * three-vertex stand-in for its text, at every step of a drag).
     */
    static final int MIN_KEPT_TRIANGLES = 256;

    /** Positions, normals, indices, and a built mesh's BVH: as a render's estimate counts a triangle. */
    public static final long BYTES_PER_TRIANGLE = 200;

    /** Where a built mesh stands: its content and its placement. */
    record Placement(String digest, Vec3 position, double scale, Vec3 rotation) {
    }

    private record Entry<T>(T value, MemoryBudget.Reservation memory) {
    }

    private final long maxTriangles;
    private final MemoryBudget memory;
    private final Map<String, Entry<MeshData>> parsed = new LinkedHashMap<>(16, 0.75f, true);
    private final Map<String, Entry<GltfModel>> models = new LinkedHashMap<>(16, 0.75f, true);
    private final Map<Placement, Entry<TriangleMesh>> built = new LinkedHashMap<>(16, 0.75f, true);
    private long triangles;

    /** @param maxTriangles at most this many triangles kept, parsed and built together */
    public MeshCache(long maxTriangles, MemoryBudget memory) {
        this.maxTriangles = maxTriangles;
        this.memory = memory;
    }

    /** Keeps nothing (the command line reads each mesh once). */
    public static MeshCache none() {
        return new MeshCache(0, MemoryBudget.unlimited());
    }

    /**
     * The key of an OBJ text's entries: its SHA-256; null in a cache that keeps nothing, which never
     * looks one up (the command line: hashing 7 MB of OBJ took 50-100 ms of a cold process).
     */
    String keyOf(String objText) {
        return maxTriangles > 0 ? digest(objText) : null;
    }

    /**
     * The key of an asset's entries: the hex SHA-256 its id carries (as {@link #keyOf} for the same OBJ
     * text, so an asset and its text inline share entries); null in a cache that keeps nothing.
     */
    String keyOfAsset(String assetId) {
        return maxTriangles > 0 ? assetId.substring(assetId.indexOf('-') + 1) : null;
    }

    /** The key of a model file's entries: its bytes' SHA-256 (as its asset id's); null in a cache that keeps nothing. */
    String keyOf(byte[] file) {
        return maxTriangles > 0 ? digest(file) : null;
    }

    /** The SHA-256 of an OBJ text. */
    private static String digest(String objText) {
        return digest(objText.getBytes(StandardCharsets.UTF_8));
    }

    private static String digest(byte[] bytes) {
        try {
            MessageDigest sha = MessageDigest.getInstance("SHA-256");
            return HexFormat.of().formatHex(sha.digest(bytes));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java runtime has SHA-256", e);
        }
    }

    synchronized MeshData parsed(String digest) {
        Entry<MeshData> entry = parsed.get(digest);
        return entry != null ? entry.value() : null;
    }

    synchronized void keepParsed(String digest, MeshData data) {
        Entry<MeshData> entry = admit(data.triangleCount(), data);
        if (entry != null) {
            release(parsed.put(digest, entry));
        }
    }

    /** A glTF model read before, by its file's digest, or null. */
    synchronized GltfModel model(String digest) {
        Entry<GltfModel> entry = models.get(digest);
        return entry != null ? entry.value() : null;
    }

    synchronized void keepModel(String digest, GltfModel model) {
        Entry<GltfModel> entry = admit(model.triangleCount(), model);
        if (entry != null) {
            release(models.put(digest, entry));
        }
    }

    synchronized TriangleMesh built(Placement placement) {
        Entry<TriangleMesh> entry = built.get(placement);
        return entry != null ? entry.value() : null;
    }

    /**
     * A built mesh of the same content, scale and rotation as {@code placement} at another position
     * (the most recently used), or null: moved there with {@link TriangleMesh#movedTo}, it is the
     * mesh the placement asks for without building its tree again.
     */
    synchronized TriangleMesh sameShape(Placement placement) {
        TriangleMesh found = null;
        for (Map.Entry<Placement, Entry<TriangleMesh>> kept : built.entrySet()) {
            Placement at = kept.getKey();
            if (at.digest().equals(placement.digest()) && at.scale() == placement.scale()
                    && at.rotation().equals(placement.rotation())) {
                found = kept.getValue().value();
            }
        }
        return found;
    }

    synchronized void keepBuilt(Placement placement, TriangleMesh mesh) {
        if (mesh.triangleCount() < MIN_KEPT_TRIANGLES) {
            return; // built again in less time than looking it up costs: an entry per placement is not worth keeping
        }
        Entry<TriangleMesh> entry = admit(mesh.triangleCount(), mesh);
        if (entry != null) {
            release(built.put(placement, entry));
        }
    }

    /** Triangles kept now. */
    synchronized long triangles() {
        return triangles;
    }

    /** Makes room (least recently used first) and reserves the memory, or null if it cannot be kept. */
    private <T> Entry<T> admit(int count, T value) {
        if (count > maxTriangles) {
            return null;
        }
        while (triangles + count > maxTriangles && evictOldest()) {
            // evicting
        }
        MemoryBudget.Reservation reservation;
        while ((reservation = memory.tryReserve(count * BYTES_PER_TRIANGLE)) == null) {
            if (!evictOldest()) {
                return null;
            }
        }
        triangles += count;
        return new Entry<>(value, reservation);
    }

    /** Drops the least recently used entry, built meshes before parsed ones and models; false if there is none. */
    private boolean evictOldest() {
        Map<?, ? extends Entry<?>> from = !built.isEmpty() ? built : !parsed.isEmpty() ? parsed : models;
        Iterator<? extends Entry<?>> oldest = from.values().iterator();
        if (!oldest.hasNext()) {
            return false;
        }
        release(oldest.next());
        oldest.remove();
        return true;
    }

    private void release(Entry<?> entry) {
        if (entry != null) {
            int count = entry.value() instanceof MeshData data ? data.triangleCount()
                    : entry.value() instanceof GltfModel model ? model.triangleCount()
                    : ((TriangleMesh) entry.value()).triangleCount();
            triangles -= count;
            entry.memory().close();
        }
    }
}

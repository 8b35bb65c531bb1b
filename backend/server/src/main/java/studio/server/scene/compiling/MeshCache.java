package studio.server.scene.compiling;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;

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

    private final LruEntries.Bound bound;
    /** Made in this order, so built meshes are evicted before parsed ones, and those before models. */
    private final LruEntries<Placement, TriangleMesh> built;
    private final LruEntries<String, MeshData> parsed;
    private final LruEntries<String, GltfModel> models;

    /** @param maxTriangles at most this many triangles kept, parsed and built together */
    public MeshCache(long maxTriangles, MemoryBudget memory) {
        bound = new LruEntries.Bound(maxTriangles, memory);
        built = bound.newMap();
        parsed = bound.newMap();
        models = bound.newMap();
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
        return bound.keepsAny() ? digest(objText) : null;
    }

    /**
     * The key of an asset's entries: the hex SHA-256 its id carries (as {@link #keyOf} for the same OBJ
     * text, so an asset and its text inline share entries); null in a cache that keeps nothing.
     */
    String keyOfAsset(String assetId) {
        return bound.keepsAny() ? assetId.substring(assetId.indexOf('-') + 1) : null;
    }

    /** The key of a model file's entries: its bytes' SHA-256 (as its asset id's); null in a cache that keeps nothing. */
    String keyOf(byte[] file) {
        return bound.keepsAny() ? digest(file) : null;
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
        return parsed.get(digest);
    }

    synchronized void keepParsed(String digest, MeshData data) {
        parsed.keep(digest, data, data.triangleCount(), data.triangleCount() * BYTES_PER_TRIANGLE);
    }

    /** A glTF model read before, by its file's digest, or null. */
    synchronized GltfModel model(String digest) {
        return models.get(digest);
    }

    synchronized void keepModel(String digest, GltfModel model) {
        models.keep(digest, model, model.triangleCount(), model.triangleCount() * BYTES_PER_TRIANGLE);
    }

    synchronized TriangleMesh built(Placement placement) {
        return built.get(placement);
    }

    /**
     * A built mesh of the same content, scale and rotation as {@code placement} at another position
     * (the most recently used), or null: moved there with {@link TriangleMesh#movedTo}, it is the
     * mesh the placement asks for without building its tree again.
     */
    synchronized TriangleMesh sameShape(Placement placement) {
        TriangleMesh[] found = {null};
        built.forEach((at, mesh) -> {
            if (at.digest().equals(placement.digest()) && at.scale() == placement.scale()
                    && at.rotation().equals(placement.rotation())) {
                found[0] = mesh;
            }
        });
        return found[0];
    }

    synchronized void keepBuilt(Placement placement, TriangleMesh mesh) {
        if (mesh.triangleCount() < MIN_KEPT_TRIANGLES) {
            return; // built again in less time than looking it up costs: an entry per placement is not worth keeping
        }
        built.keep(placement, mesh, mesh.triangleCount(), mesh.triangleCount() * BYTES_PER_TRIANGLE);
    }

    /** Triangles kept now. */
    synchronized long triangles() {
        return bound.size();
    }
}

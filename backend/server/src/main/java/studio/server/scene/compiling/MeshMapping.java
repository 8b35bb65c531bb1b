package studio.server.scene.compiling;

import static studio.server.scene.compiling.FormatValues.or;
import static studio.server.scene.compiling.FormatValues.vec;

import java.nio.charset.StandardCharsets;
import java.util.function.Supplier;

import studio.engine.geometry.TriangleMesh;
import studio.engine.memory.MemoryGate;
import studio.engine.mesh.MeshData;
import studio.engine.mesh.ObjReader;
import studio.engine.mesh.TooManyTrianglesException;
import studio.server.scene.format.ObjectDto;
import studio.server.scene.format.SceneDefaults;

/**
 * The meshes of one scene: each one's OBJ text (inline, from its file or its asset), parsed and built or
 * taken from the {@link MeshCache}, within the server's triangle limit for all of the scene's
 * meshes together.
 */
final class MeshMapping {

    private final MeshCache cache;
    private final MeshFiles files;
    private final MeshAssets assets;
    private final MemoryGate memory;
    private final MappingProblems problems;
    /** Triangles the scene may still have. */
    private final TriangleBudget budget;

    MeshMapping(TriangleBudget budget, MeshCache cache, MeshFiles files, MeshAssets assets, MemoryGate memory,
                MappingProblems problems) {
        this.budget = budget;
        this.cache = cache;
        this.files = files;
        this.assets = assets;
        this.memory = memory;
        this.problems = problems;
    }

    /** The mesh placed in the scene, or null (and a problem) if it cannot be. */
    TriangleMesh of(ObjectDto.Mesh mesh, String path) {
        Source source = source(mesh, path);
        MeshData data = source != null ? meshData(source) : null;
        if (data == null) {
            return null;
        }
        String digest = source.digest();
        budget.spend(data.triangleCount());
        MeshCache.Placement placement = new MeshCache.Placement(digest,
                vec(or(mesh.position(), SceneDefaults.ORIGIN)), or(mesh.scale(), SceneDefaults.MESH_SCALE),
                vec(or(mesh.rotation(), SceneDefaults.ORIGIN)));
        TriangleMesh shape = cache.built(placement);
        if (shape == null) {
            TriangleMesh elsewhere = cache.sameShape(placement);
            shape = problems.attempt(path, () -> elsewhere != null ? elsewhere.movedTo(placement.position(), memory)
                    : new TriangleMesh(data, placement.position(), placement.scale(), placement.rotation(), memory));
            if (shape != null) {
                cache.keepBuilt(placement, shape);
            }
        }
        return shape;
    }

    /**
     * A mesh's OBJ text, its cache key, and the field it came from.
     *
     * @param text   the OBJ text, decoded when first asked for (an asset's bytes need not be, if its mesh is cached)
     * @param digest the key of its {@link MeshCache} entries (null in a cache that keeps nothing)
     */
    private record Source(Supplier<String> text, String digest, String field) {
    }

    /** Where the mesh's OBJ comes from: inline, its file or its asset; null (and a problem) if none. */
    private Source source(ObjectDto.Mesh mesh, String path) {
        int given = (mesh.obj() != null ? 1 : 0) + (mesh.file() != null ? 1 : 0) + (mesh.asset() != null ? 1 : 0);
        if (given != 1) {
            problems.add(path, given == 0 ? "a mesh needs its OBJ text in \"obj\", a \"file\" name or an \"asset\" id"
                    : "give the mesh one of \"obj\", \"file\" and \"asset\", not more");
            return null;
        }
        if (mesh.asset() != null) {
            String field = path + ".asset";
            byte[] bytes = problems.attempt(field, () -> assets.obj(mesh.asset()));
            if (bytes == null) {
                if (!problems.has(field)) {
                    problems.add(field, "this server has no asset " + mesh.asset() + "; upload it (POST /api/assets) "
                            + "and send the scene again");
                }
                return null;
            }
            return new Source(() -> new String(bytes, StandardCharsets.UTF_8), cache.keyOfAsset(mesh.asset()), field);
        }
        String text = mesh.obj() != null ? mesh.obj() : problems.attempt(path + ".file", () -> files.read(mesh.file()));
        return text == null ? null
                : new Source(() -> text, cache.keyOf(text), path + (mesh.obj() != null ? ".obj" : ".file"));
    }

    /**
     * The OBJ data of a mesh's text (read before, or parsed now and kept); null (and a problem) if it
     * does not parse, or it has more triangles than the scene may still have (the reader stops there,
     * so a text of millions of triangles costs no more than the budget's worth).
     */
    private MeshData meshData(Source source) {
        String digest = source.digest();
        String field = source.field();
        int triangleBudget = budget.left();
        MeshData data = cache.parsed(digest);
        if (data == null) {
            try {
                data = ObjReader.parse(source.text().get(), Math.max(0, triangleBudget), memory);
            } catch (TooManyTrianglesException e) {
                problems.add(field, "has more than " + triangleBudget + " triangles (passed at OBJ line " + e.line()
                        + "); this server's limit is " + triangleBudget + " more (all meshes together, "
                        + "studio.limits.max-triangles)");
                return null;
            } catch (IllegalArgumentException e) {
                problems.add(field, "is not a usable OBJ mesh: " + e.getMessage());
                return null;
            }
            cache.keepParsed(digest, data);
        }
        if (data.triangleCount() > triangleBudget) {
            problems.add(field, "has " + data.triangleCount() + " triangles; this server's limit is "
                    + (triangleBudget < 0 ? 0 : triangleBudget) + " more (all meshes together, "
                    + "studio.limits.max-triangles)");
            return null;
        }
        return data;
    }
}

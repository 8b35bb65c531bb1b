package studio.server.scene.compiling;

import static studio.server.scene.compiling.FormatValues.or;
import static studio.server.scene.compiling.FormatValues.vec;

import studio.engine.geometry.TriangleMesh;
import studio.engine.memory.MemoryGate;
import studio.engine.mesh.MeshData;
import studio.engine.mesh.ObjReader;
import studio.engine.mesh.TooManyTrianglesException;
import studio.server.scene.format.ObjectDto;
import studio.server.scene.format.SceneDefaults;

/**
 * The meshes of one scene: each one's OBJ text (inline or from its file), parsed and built or
 * taken from the {@link MeshCache}, within the server's triangle limit for all of the scene's
 * meshes together.
 */
final class MeshMapping {

    private final MeshCache cache;
    private final MeshFiles files;
    private final MemoryGate memory;
    private final MappingProblems problems;
    /** Triangles the scene may still have. */
    private int triangleBudget;

    MeshMapping(int maxTriangles, MeshCache cache, MeshFiles files, MemoryGate memory, MappingProblems problems) {
        this.triangleBudget = maxTriangles;
        this.cache = cache;
        this.files = files;
        this.memory = memory;
        this.problems = problems;
    }

    /** The mesh placed in the scene, or null (and a problem) if it cannot be. */
    TriangleMesh of(ObjectDto.Mesh mesh, String path) {
        String text = meshText(mesh, path);
        String digest = text != null ? cache.keyOf(text) : null;
        MeshData data = text != null ? meshData(text, digest, meshField(mesh, path)) : null;
        if (data == null) {
            return null;
        }
        triangleBudget -= data.triangleCount();
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

    /** The mesh's OBJ text, inline or from its file; null (and a problem) if there is none. */
    private String meshText(ObjectDto.Mesh mesh, String path) {
        if ((mesh.obj() == null) == (mesh.file() == null)) {
            problems.add(path, mesh.obj() == null ? "a mesh needs its OBJ text in \"obj\" or a \"file\" name"
                    : "give the mesh either \"obj\" or \"file\", not both");
            return null;
        }
        return mesh.obj() != null ? mesh.obj() : problems.attempt(path + ".file", () -> files.read(mesh.file()));
    }

    /** The field that holds the mesh's OBJ: its {@code obj} or its {@code file}. */
    private static String meshField(ObjectDto.Mesh mesh, String path) {
        return path + (mesh.obj() != null ? ".obj" : ".file");
    }

    /**
     * The OBJ data of a mesh's text (read before, or parsed now and kept); null (and a problem) if it
     * does not parse, or it has more triangles than the scene may still have (the reader stops there,
     * so a text of millions of triangles costs no more than the budget's worth).
     */
    private MeshData meshData(String text, String digest, String field) {
        MeshData data = cache.parsed(digest);
        if (data == null) {
            try {
                data = ObjReader.parse(text, Math.max(0, triangleBudget), memory);
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

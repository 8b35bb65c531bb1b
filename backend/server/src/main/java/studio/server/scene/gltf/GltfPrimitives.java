package studio.server.scene.gltf;

import static studio.server.scene.gltf.GltfJson.bad;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import java.util.Set;

import tools.jackson.databind.JsonNode;

import studio.engine.memory.MemoryGate;

/**
 * A glTF mesh's triangle primitives (mode 4), read once however many nodes place them: positions,
 * normals (dropped, with a warning, if one is zero), TEXCOORD_0, and the indices (0, 1, 2, ... for a
 * primitive without). Other modes, morph targets and attributes that are not drawn are warnings.
 */
final class GltfPrimitives {

    /** A primitive's vertex data in its mesh's space. */
    record Primitive(double[] positions, double[] normals, double[] uvs, int[] indices, int material) {
        int vertexCount() {
            return positions.length / 3;
        }
    }

    private static final Set<Integer> POSITION_TYPES = Set.of(5126, 5120, 5121, 5122, 5123);
    private static final Set<Integer> NORMAL_TYPES = Set.of(5126, 5120, 5122);
    private static final Set<Integer> TEXCOORD_TYPES = Set.of(5126, 5120, 5121, 5122, 5123);
    private static final String[] MODE_NAMES = {"points", "lines", "line loops", "line strips", "triangles",
        "triangle strips", "triangle fans"};

    private final JsonNode meshes;
    private final GltfAccessors accessors;
    private final int materials;
    private final Set<String> warnings;
    private final Map<String, Primitive> read = new HashMap<>();
    /** Each vertex's number in the primitive being compacted, or -1: one table for all, reset after each. */
    private int[] renumbered = new int[0];

    GltfPrimitives(JsonNode root, GltfAccessors accessors, int materials, Set<String> warnings) {
        this.meshes = GltfJson.array(root, "meshes", "");
        this.accessors = accessors;
        this.materials = materials;
        this.warnings = warnings;
    }

    /** The primitives of mesh {@code m}. */
    JsonNode of(int m) {
        JsonNode mesh = GltfJson.element(meshes, m, "meshes");
        if (!mesh.path("weights").isMissingNode()) {
            warnings.add("meshes[" + m + "]: morph target weights are not applied");
        }
        return GltfJson.array(mesh, "primitives", "meshes[" + m + "].");
    }

    /** The triangles primitive {@code p} of mesh {@code m} draws (from the counts alone; 0 if it is not drawn). */
    long triangles(int m, int p) {
        String path = path(m, p);
        JsonNode prim = GltfJson.element(of(m), p, path(m, -1));
        if (mode(prim, path) != 4 || prim.path("attributes").path("POSITION").isMissingNode()) {
            return 0;
        }
        JsonNode attributes = prim.path("attributes");
        int position = GltfJson.index(attributes, "POSITION", accessors.size(), "accessors", path + ".attributes");
        int indices = GltfJson.optionalIndex(prim, "indices", accessors.size(), "accessors", path);
        return (indices >= 0 ? accessors.count(indices) : accessors.count(position)) / 3;
    }

    /** Primitive {@code p} of mesh {@code m}, or null (and a warning) if it is not drawn. */
    Primitive read(int m, int p) {
        String key = m + "/" + p;
        if (!read.containsKey(key)) {
            read.put(key, load(m, p));
        }
        return read.get(key);
    }

    private Primitive load(int m, int p) {
        String path = path(m, p);
        JsonNode prim = GltfJson.element(of(m), p, path(m, -1));
        int mode = mode(prim, path);
        if (mode != 4) {
            warnings.add(path + ": " + MODE_NAMES[mode] + " (mode " + mode + ") are not drawn, only triangles");
            return null;
        }
        if (!prim.path("targets").isMissingNode()) {
            warnings.add(path + ": morph targets are not applied");
        }
        for (String extension : prim.path("extensions").propertyNames()) {
            warnings.add(path + ": the extension " + extension + " is not applied");
        }
        JsonNode attributes = prim.path("attributes");
        if (!attributes.isObject()) {
            throw bad(path + ".attributes", "must be an object");
        }
        for (String name : attributes.propertyNames()) {
            if (!Set.of("POSITION", "NORMAL", "TEXCOORD_0", "TANGENT").contains(name)
                    && !name.startsWith("JOINTS_") && !name.startsWith("WEIGHTS_")) {
                warnings.add(path + ": the attribute " + name + " is not drawn");
            }
        }
        if (attributes.path("POSITION").isMissingNode()) {
            warnings.add(path + ": it has no POSITION, so it is not drawn");
            return null;
        }
        String at = path + ".attributes";
        int position = GltfJson.index(attributes, "POSITION", accessors.size(), "accessors", at);
        double[] positions = accessors.numbers(position, "VEC3", 3, POSITION_TYPES, at + ".POSITION");
        int vertices = positions.length / 3;
        double[] normals = sameCount(attributes, "NORMAL", "VEC3", 3, NORMAL_TYPES, vertices, at);
        if (normals != null && hasZero(normals)) {
            warnings.add(path + ": a NORMAL is zero, so its triangles are shaded flat");
            normals = null;
        }
        double[] uvs = sameCount(attributes, "TEXCOORD_0", "VEC2", 2, TEXCOORD_TYPES, vertices, at);
        int indexAccessor = GltfJson.optionalIndex(prim, "indices", accessors.size(), "accessors", path);
        int[] indices;
        if (indexAccessor >= 0) {
            indices = accessors.indices(indexAccessor, vertices);
        } else {
            accessors.memory().reserve(MemoryGate.ints(vertices));
            indices = new int[vertices];
            for (int i = 0; i < vertices; i++) {
                indices[i] = i;
            }
        }
        if (indices.length % 3 != 0) {
            throw bad(path, "its " + indices.length + " vertices (indexed or not) are not a whole number of triangles");
        }
        int material = GltfJson.optionalIndex(prim, "material", materials, "materials", path);
        return compacted(new Primitive(positions, normals, uvs, indices, material));
    }

    /**
     * The primitive with only the vertices its triangles use, numbered in the order they are first
     * used: primitives that share a large vertex buffer, each using part of it, then cost no more than
     * their triangles (at most 3 vertices a triangle), whatever the buffer's size.
     */
    private Primitive compacted(Primitive p) {
        int[] indices = p.indices();
        int vertices = p.vertexCount();
        if (renumbered.length < vertices) {
            accessors.memory().reserve(MemoryGate.ints(vertices));
            renumbered = new int[vertices];
            Arrays.fill(renumbered, -1);
        }
        accessors.memory().reserve(MemoryGate.ints(indices.length));
        int used = 0;
        boolean inOrder = true;
        int[] compact = new int[indices.length];
        for (int i = 0; i < indices.length; i++) {
            int v = indices[i];
            if (renumbered[v] < 0) {
                inOrder &= v == used;
                renumbered[v] = used++;
            }
            compact[i] = renumbered[v];
        }
        try {
            if (used == vertices && inOrder) {
                return p;
            }
            accessors.memory().reserve(MemoryGate.doubles(3L * used) * (p.normals() != null ? 2 : 1)
                    + (p.uvs() != null ? MemoryGate.doubles(2L * used) : 0));
            double[] positions = new double[3 * used];
            double[] normals = p.normals() != null ? new double[3 * used] : null;
            double[] uvs = p.uvs() != null ? new double[2 * used] : null;
            for (int v : indices) {
                int to = renumbered[v];
                System.arraycopy(p.positions(), 3 * v, positions, 3 * to, 3);
                if (normals != null) {
                    System.arraycopy(p.normals(), 3 * v, normals, 3 * to, 3);
                }
                if (uvs != null) {
                    System.arraycopy(p.uvs(), 2 * v, uvs, 2 * to, 2);
                }
            }
            return new Primitive(positions, normals, uvs, compact, p.material());
        } finally {
            for (int v : indices) {
                renumbered[v] = -1;
            }
        }
    }

    private double[] sameCount(JsonNode attributes, String name, String type, int components, Set<Integer> types,
                               int vertices, String path) {
        int accessor = GltfJson.optionalIndex(attributes, name, accessors.size(), "accessors", path);
        if (accessor < 0) {
            return null;
        }
        double[] values = accessors.numbers(accessor, type, components, types, path + "." + name);
        if (values.length / components != vertices) {
            throw bad(path + "." + name, "has " + values.length / components + " elements, but POSITION has " + vertices);
        }
        return values;
    }

    private static boolean hasZero(double[] normals) {
        for (int i = 0; i < normals.length; i += 3) {
            if (normals[i] == 0 && normals[i + 1] == 0 && normals[i + 2] == 0) {
                return true;
            }
        }
        return false;
    }

    private static int mode(JsonNode prim, String path) {
        return (int) GltfJson.whole(prim, "mode", 0, 6, 4, path);
    }

    private static String path(int m, int p) {
        return "meshes[" + m + "].primitives" + (p >= 0 ? "[" + p + "]" : "");
    }
}

package studio.server.scene.gltf;

import static studio.server.scene.gltf.GltfJson.bad;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import tools.jackson.databind.JsonNode;

import studio.engine.math.Affine;
import studio.engine.memory.MemoryGate;
import studio.engine.mesh.MeshData;

/**
 * A .glb or .gltf read into a {@link GltfModel}: the default scene's nodes ({@link GltfNodes}), their
 * meshes' triangle primitives ({@link GltfPrimitives}) placed by the nodes' transforms, grouped into
 * one engine mesh per material (and per whether they have normals and TEXCOORD_0), and the materials
 * mapped ({@link GltfMaterials}). A transform that mirrors turns its triangles' winding back, so their
 * normals still face out.
 *
 * <p>The triangle count is worked out from the accessors' counts and checked against the limit before
 * any vertex is read. A file that is broken (its container, its JSON, an index, offset, count or stride
 * out of range) or that requires an extension this reader lacks is refused with an
 * IllegalArgumentException naming the place by its JSON path in the file.
 */
public final class GltfReader {

    /** The extensions read; a file that requires any other is refused. */
    static final Set<String> READ_EXTENSIONS = Set.of("KHR_materials_transmission", "KHR_materials_ior",
            "KHR_materials_emissive_strength", "KHR_mesh_quantization");

    private GltfReader() {
    }

    /** Thrown when a model has more triangles than it may. */
    public static final class TooManyTrianglesException extends IllegalArgumentException {
        private final long triangles;

        TooManyTrianglesException(long triangles, int limit) {
            super("it draws " + triangles + " triangles; the limit here is " + limit);
            this.triangles = triangles;
        }

        public long triangles() {
            return triangles;
        }
    }

    /**
     * @param assets       where buffers and images named by asset id are read from
     * @param maxTriangles the most triangles the model may draw (all its instances together)
     * @param memory       asked before every array that grows with the file is allocated
     * @throws IllegalArgumentException saying what is wrong with the file
     */
    public static GltfModel read(byte[] bytes, GltfAssets assets, int maxTriangles, MemoryGate memory) {
        GltfSource source = GltfSource.of(bytes);
        JsonNode root = source.root();
        Set<String> warnings = new LinkedHashSet<>();
        extensions(root, warnings);
        for (String unused : new String[] {"animations", "skins", "cameras"}) {
            if (!GltfJson.array(root, unused, "").isEmpty()) {
                warnings.add(unused + ": the file's " + unused + " are not used");
            }
        }
        GltfBuffers buffers = new GltfBuffers(root, source.bin(), assets);
        GltfAccessors accessors = new GltfAccessors(root, buffers, memory);
        GltfMaterials materials = new GltfMaterials(root, new GltfImages(root, buffers, assets, warnings), warnings);
        GltfPrimitives primitives = new GltfPrimitives(root, accessors, materials.size(), warnings);
        List<GltfNodes.Instance> instances = GltfNodes.walk(root, warnings);

        // each mesh's triangles and primitives once, then each instance's: linear in the file, whatever it nests
        Map<Integer, long[]> perMesh = new HashMap<>();
        long triangles = 0, placed = 0;
        for (GltfNodes.Instance instance : instances) {
            long[] counts = perMesh.computeIfAbsent(instance.mesh(), m -> {
                int count = primitives.of(m).size();
                long sum = 0;
                for (int p = 0; p < count; p++) {
                    sum += primitives.triangles(m, p);
                }
                return new long[] {sum, count};
            });
            triangles += counts[0];
            placed += counts[1];
        }
        if (triangles > maxTriangles) {
            throw new TooManyTrianglesException(triangles, maxTriangles);
        }
        if (placed > maxTriangles) {
            throw bad("nodes", "they place " + placed + " primitives; at most " + maxTriangles + " are read (as many "
                    + "as triangles)");
        }

        Map<Group, List<Placed>> groups = new LinkedHashMap<>();
        for (GltfNodes.Instance instance : instances) {
            double det = instance.modelFromMesh().determinant();
            if (det == 0 || !Double.isFinite(det)) {
                warnings.add(instance.node() + ": its transform flattens or overflows its mesh, so it is not drawn");
                continue;
            }
            for (int p = 0; p < primitives.of(instance.mesh()).size(); p++) {
                GltfPrimitives.Primitive prim = primitives.read(instance.mesh(), p);
                if (prim != null) {
                    Group key = new Group(prim.material(), prim.normals() != null, prim.uvs() != null);
                    groups.computeIfAbsent(key, k -> new ArrayList<>()).add(new Placed(prim, instance.modelFromMesh()));
                }
            }
        }
        List<GltfPart> parts = new ArrayList<>();
        Map<Integer, GltfMaterials.Mapped> mapped = new LinkedHashMap<>();
        for (Map.Entry<Group, List<Placed>> group : groups.entrySet()) {
            GltfMaterials.Mapped material = mapped.computeIfAbsent(group.getKey().material(), materials::of);
            parts.add(part(group.getKey(), group.getValue(), material, memory));
        }
        if (parts.isEmpty()) {
            throw bad("scenes", "the default scene draws no triangles");
        }
        return new GltfModel(parts, listed(warnings));
    }

    /** The most warnings an answer lists; a file of 10,000 cameras gets the first of them and a count. */
    static final int MAX_WARNINGS = 50;

    private static List<String> listed(Set<String> warnings) {
        List<String> all = new ArrayList<>(warnings);
        if (all.size() <= MAX_WARNINGS) {
            return all;
        }
        List<String> first = new ArrayList<>(all.subList(0, MAX_WARNINGS));
        first.add("and " + (all.size() - MAX_WARNINGS) + " more warnings of the same kinds");
        return first;
    }

    /** Primitives that become one engine mesh: one material, all with normals and TEXCOORD_0 or all without. */
    private record Group(int material, boolean normals, boolean uvs) {
    }

    private record Placed(GltfPrimitives.Primitive primitive, Affine transform) {
    }

    private static GltfPart part(Group group, List<Placed> placed, GltfMaterials.Mapped material, MemoryGate memory) {
        long vertices = 0, indices = 0;
        for (Placed p : placed) {
            vertices += p.primitive().vertexCount();
            indices += p.primitive().indices().length;
        }
        if (3 * vertices > Integer.MAX_VALUE - 8 || indices > Integer.MAX_VALUE - 8) {
            throw bad("meshes", "a material's primitives have too many vertices together (" + vertices + ")");
        }
        memory.reserve(MemoryGate.doubles(3 * vertices) * (group.normals() ? 2 : 1)
                + (group.uvs() ? MemoryGate.doubles(2 * vertices) : 0) + MemoryGate.ints(indices));
        double[] positions = new double[(int) (3 * vertices)];
        double[] normals = group.normals() ? new double[positions.length] : null;
        double[] uvs = group.uvs() ? new double[(int) (2 * vertices)] : null;
        int[] triangles = new int[(int) indices];
        int base = 0, at = 0;
        for (Placed p : placed) {
            GltfPrimitives.Primitive prim = p.primitive();
            int n = prim.vertexCount();
            p.transform().applyToPoints(prim.positions(), n, positions, 3 * base);
            if (normals != null) {
                p.transform().applyToNormals(prim.normals(), n, normals, 3 * base);
            }
            if (uvs != null) {
                double[] from = prim.uvs();
                for (int k = 0; k < n; k++) {
                    uvs[2 * (base + k)] = from[2 * k];
                    uvs[2 * (base + k) + 1] = 1 - from[2 * k + 1]; // glTF's v runs down the image, the engine's up
                }
            }
            boolean mirrored = p.transform().determinant() < 0;
            int[] ix = prim.indices();
            for (int t = 0; t < ix.length; t += 3) {
                triangles[at++] = base + ix[t];
                triangles[at++] = base + ix[mirrored ? t + 2 : t + 1];
                triangles[at++] = base + ix[mirrored ? t + 1 : t + 2];
            }
            base += n;
        }
        MeshData mesh;
        try {
            mesh = new MeshData(positions, triangles, normals, uvs);
        } catch (IllegalArgumentException e) {
            throw bad("nodes", "the nodes' transforms place a vertex out of range: " + e.getMessage());
        }
        return new GltfPart(mesh, uvs, material.material(), material.texture());
    }

    private static void extensions(JsonNode root, Set<String> warnings) {
        JsonNode required = GltfJson.array(root, "extensionsRequired", "");
        for (int i = 0; i < required.size(); i++) {
            String name = required.get(i).asString("");
            if (!READ_EXTENSIONS.contains(name)) {
                throw bad("extensionsRequired[" + i + "]", "the file requires " + name + ", which is not supported");
            }
        }
        JsonNode used = GltfJson.array(root, "extensionsUsed", "");
        for (int i = 0; i < used.size(); i++) {
            String name = used.get(i).asString("");
            if (!READ_EXTENSIONS.contains(name)) {
                warnings.add("extensionsUsed: " + name + " is not supported; what it adds is not drawn");
            }
        }
    }
}

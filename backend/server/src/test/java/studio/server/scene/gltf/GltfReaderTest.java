package studio.server.scene.gltf;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import tools.jackson.databind.node.ObjectNode;

import studio.engine.material.MaterialKind;
import studio.engine.memory.MemoryGate;
import studio.engine.mesh.MeshData;

class GltfReaderTest {

    static GltfModel read(byte[] bytes) {
        return GltfReader.read(bytes, GltfAssets.none(), 1_000_000, MemoryGate.UNLIMITED);
    }

    private static void assertVertex(MeshData mesh, int v, double x, double y, double z) {
        double[] p = mesh.positions();
        assertArrayEquals(new double[] {x, y, z}, new double[] {p[3 * v], p[3 * v + 1], p[3 * v + 2]}, 1e-12,
                "vertex " + v);
    }

    @Test
    void placesATriangleByNestedTranslationRotationAndScale() {
        // parent: scale 2, then 90 degrees about y ((x, y, z) -> (z, y, -x)), then moved by (1, 2, 3);
        // child: scale y by 3, then moved up 1
        double s = Math.sqrt(0.5);
        ObjectNode gltf = TestGltf.triangle("""
                [{"translation": [1, 2, 3], "rotation": [0, %s, 0, %s], "scale": [2, 2, 2], "children": [1]},
                 {"translation": [0, 1, 0], "scale": [1, 3, 1], "mesh": 0}]""".formatted(s, s));
        GltfModel model = read(TestGltf.bytes(gltf));
        assertEquals(1, model.parts().size());
        MeshData mesh = model.parts().get(0).mesh();
        assertVertex(mesh, 0, 1, 4, 3);
        assertVertex(mesh, 1, 1, 4, 1);
        assertVertex(mesh, 2, 1, 10, 3);
        assertEquals(List.of(), model.warnings());
    }

    @Test
    void placesByAColumnMajorMatrixAsByItsTrs() {
        ObjectNode gltf = TestGltf.triangle("[{\"matrix\": [0, 0, -2, 0, 0, 2, 0, 0, 2, 0, 0, 0, 1, 2, 3, 1]}]");
        ((ObjectNode) gltf.get("nodes").get(0)).put("mesh", 0);
        MeshData mesh = read(TestGltf.bytes(gltf)).parts().get(0).mesh();
        assertVertex(mesh, 1, 1, 2, 1);
        assertVertex(mesh, 2, 1, 4, 3);
    }

    @Test
    void mirroringTransformTurnsTheWindingBack() {
        ObjectNode gltf = TestGltf.triangle("[{\"scale\": [-1, 1, 1], \"mesh\": 0}]");
        MeshData mesh = read(TestGltf.bytes(gltf)).parts().get(0).mesh();
        assertArrayEquals(new int[] {0, 2, 1}, mesh.indices());
    }

    @Test
    void readsAGlbAsItsGltf() {
        ObjectNode gltf = TestGltf.triangle("[{\"translation\": [0, 0, 5], \"mesh\": 0}]");
        MeshData mesh = read(TestGltf.glb(gltf, TestGltf.triangleBuffer())).parts().get(0).mesh();
        assertVertex(mesh, 2, 0, 1, 5);
    }

    @Test
    void instancesOfOneMeshShareTheirMaterialsMesh() {
        ObjectNode gltf = TestGltf.triangle("""
                [{"children": [1, 2]}, {"mesh": 0}, {"translation": [10, 0, 0], "mesh": 0}]""");
        GltfModel model = read(TestGltf.bytes(gltf));
        assertEquals(1, model.parts().size());
        assertEquals(2, model.triangleCount());
        assertVertex(model.parts().get(0).mesh(), 4, 11, 0, 0);
        assertArrayEquals(new int[] {0, 1, 2, 3, 4, 5}, model.parts().get(0).mesh().indices());
    }

    @Test
    void readsKhronosBox() {
        GltfModel model = read(TestGltf.khronos("Box/Box.gltf"));
        GltfPart part = model.parts().get(0);
        assertEquals(12, part.mesh().triangleCount());
        assertTrue(part.mesh().hasNormals());
        for (double c : part.mesh().positions()) {
            assertEquals(0.5, Math.abs(c), 1e-7);
        }
        // baseColorFactor 0.8, 0, 0 with glTF's default metallic 1, roughness 1: a rough red metal
        assertEquals(MaterialKind.METAL, part.material().kind());
        assertEquals(0.800000011920929, part.material().color().r(), 0);
        assertEquals(0, part.material().reflectivity(), 0);
        assertEquals(0.8, part.material().diffuse(), 1e-12); // fully rough: its colour shows as a plastic's would
        assertEquals(List.of(), model.warnings());
    }

    @Test
    void readsKhronosBoxTexturedWithItsUvsAndImage() {
        GltfModel model = read(TestGltf.khronos("BoxTextured/BoxTextured.gltf"));
        GltfPart part = model.parts().get(0);
        assertEquals(12, part.mesh().triangleCount());
        assertNotNull(part.uvs());
        assertEquals(48, part.uvs().length);
        assertEquals(6, part.uvs()[0], 0); // the first TEXCOORD_0 is (6, 0): v turned up, 1 - 0
        assertEquals(1, part.uvs()[1], 0);
        assertEquals("image/png", part.texture().mediaType());
        assertEquals(2433, part.texture().image().length);
        assertEquals("images[0]", part.texture().source());
    }

    @Test
    void mapsMaterialsOntoTheSix() {
        ObjectNode gltf = TestGltf.triangle();
        ObjectNode material = (ObjectNode) gltf.get("materials").get(0);
        assertEquals(MaterialKind.PLASTIC, read(TestGltf.bytes(gltf)).parts().get(0).material().kind());
        ((ObjectNode) material.get("pbrMetallicRoughness")).put("metallicFactor", 0.9).put("roughnessFactor", 0.5);
        var metal = read(TestGltf.bytes(gltf)).parts().get(0).material();
        assertEquals(MaterialKind.METAL, metal.kind());
        assertEquals(30, metal.shininess(), 1e-9); // a = 0.25: 2 / 0.0625 - 2
        assertEquals(0.25, metal.reflectivity(), 1e-12);
        assertEquals(0.475, metal.diffuse(), 1e-12);
        material.set("extensions", TestGltf.JSON.readTree(
                "{\"KHR_materials_transmission\": {\"transmissionFactor\": 1}, \"KHR_materials_ior\": {\"ior\": 1.33}}"));
        var glass = read(TestGltf.bytes(gltf)).parts().get(0).material();
        assertEquals(MaterialKind.GLASS, glass.kind());
        assertEquals(1.33, glass.ior(), 0);
        material.set("emissiveFactor", TestGltf.JSON.readTree("[0, 1, 0.5]"));
        var flat = read(TestGltf.bytes(gltf)).parts().get(0).material();
        assertEquals(MaterialKind.FLAT, flat.kind());
        assertEquals(0.5, flat.color().b(), 0);
    }

    @Test
    void listsWhatItDoesNotDraw() {
        ObjectNode gltf = TestGltf.triangle("[{\"mesh\": 0, \"skin\": 0, \"camera\": 0}]");
        gltf.set("animations", TestGltf.JSON.readTree("[{\"channels\": [], \"samplers\": []}]"));
        gltf.set("extensionsUsed", TestGltf.JSON.readTree("[\"KHR_lights_punctual\"]"));
        ObjectNode mesh = (ObjectNode) gltf.get("meshes").get(0);
        mesh.withArray("primitives").add(TestGltf.JSON.readTree("{\"attributes\": {\"POSITION\": 0}, \"mode\": 1}"));
        List<String> warnings = read(TestGltf.bytes(gltf)).warnings();
        assertTrue(warnings.contains("animations: the file's animations are not used"), warnings::toString);
        assertTrue(warnings.contains("nodes[0]: skins are not applied; the mesh is drawn in its bind pose"));
        assertTrue(warnings.contains("nodes[0]: cameras are not used (the scene's camera is)"));
        assertTrue(warnings.contains("extensionsUsed: KHR_lights_punctual is not supported; what it adds is not drawn"));
        assertTrue(warnings.contains("meshes[0].primitives[1]: lines (mode 1) are not drawn, only triangles"));
    }

    @Test
    void readsInterleavedVerticesAndSmallComponentTypes() {
        // one view of (position, normal) pairs at a stride of 24; TEXCOORD_0 as normalized unsigned bytes
        // (padded to 4 a vertex); the indices as unsigned bytes
        java.nio.ByteBuffer b = java.nio.ByteBuffer.allocate(72 + 12 + 4).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        float[][] corners = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        for (float[] c : corners) {
            b.putFloat(c[0]).putFloat(c[1]).putFloat(c[2]).putFloat(0).putFloat(0).putFloat(2);
        }
        b.put(new byte[] {0, 0, 0, 0, (byte) 255, 0, 0, 0, 0, (byte) 255, 0, 0});
        b.put(new byte[] {2, 1, 0, 0});
        ObjectNode gltf = TestGltf.triangle();
        gltf.set("accessors", TestGltf.JSON.readTree("""
                [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                 {"bufferView": 2, "componentType": 5121, "count": 3, "type": "SCALAR"},
                 {"bufferView": 0, "byteOffset": 12, "componentType": 5126, "count": 3, "type": "VEC3"},
                 {"bufferView": 1, "componentType": 5121, "normalized": true, "count": 3, "type": "VEC2"}]"""));
        gltf.set("bufferViews", TestGltf.JSON.readTree("""
                [{"buffer": 0, "byteLength": 72, "byteStride": 24},
                 {"buffer": 0, "byteOffset": 72, "byteLength": 12, "byteStride": 4},
                 {"buffer": 0, "byteOffset": 84, "byteLength": 3}]"""));
        ((ObjectNode) gltf.get("meshes").get(0).get("primitives").get(0)).set("attributes",
                TestGltf.JSON.readTree("{\"POSITION\": 0, \"NORMAL\": 2, \"TEXCOORD_0\": 3}"));
        ((ObjectNode) gltf.get("buffers").get(0)).put("byteLength", 88);
        GltfPart part = read(TestGltf.glb(gltf, b.array())).parts().get(0);
        MeshData mesh = part.mesh();
        // the indices 2, 1, 0 renumber the vertices in the order they are used
        assertArrayEquals(new int[] {0, 1, 2}, mesh.indices());
        assertVertex(mesh, 0, 0, 1, 0);
        assertVertex(mesh, 2, 0, 0, 0);
        assertArrayEquals(new double[] {0, 0, 1, 0, 0, 1, 0, 0, 1}, mesh.normals(), 0);
        // TEXCOORD_0 (0, 1), (1, 0), (0, 0) in the order used, v turned up
        assertArrayEquals(new double[] {0, 0, 1, 1, 0, 1}, part.uvs(), 0);
    }

    @Test
    void listsAtMostFiftyWarningsAndHowManyMore() {
        StringBuilder nodes = new StringBuilder("[{\"mesh\": 0, \"children\": [");
        for (int i = 1; i <= 60; i++) {
            nodes.append(i).append(i < 60 ? "," : "]}");
        }
        nodes.append(",{\"camera\": 0}".repeat(60)).append("]");
        List<String> warnings = read(TestGltf.bytes(TestGltf.triangle(nodes.toString()))).warnings();
        assertEquals(51, warnings.size());
        assertEquals("nodes[1]: cameras are not used (the scene's camera is)", warnings.get(0));
        assertEquals("and 10 more warnings of the same kinds", warnings.get(50));
    }

    @Test
    void readsAnImageFromTheGlbsBinChunk() {
        byte[] png = TestGltf.khronos("BoxTextured/BoxTextured.gltf"); // its PNG, decoded from its data: URI below
        String text = new String(png, java.nio.charset.StandardCharsets.UTF_8);
        int at = text.indexOf("data:image/png;base64,") + "data:image/png;base64,".length();
        byte[] image = java.util.Base64.getDecoder().decode(text.substring(at, text.indexOf('"', at)));
        byte[] bin = java.util.Arrays.copyOf(TestGltf.triangleBuffer(), 44 + (image.length + 3) / 4 * 4);
        System.arraycopy(image, 0, bin, 44, image.length);
        ObjectNode gltf = TestGltf.triangle();
        gltf.withArray("bufferViews").add(TestGltf.JSON.readTree(
                "{\"buffer\": 0, \"byteOffset\": 44, \"byteLength\": " + image.length + "}"));
        gltf.set("images", TestGltf.JSON.readTree("[{\"bufferView\": 2, \"mimeType\": \"image/png\"}]"));
        gltf.set("textures", TestGltf.JSON.readTree("[{\"source\": 0}]"));
        ((ObjectNode) gltf.get("materials").get(0).get("pbrMetallicRoughness"))
                .set("baseColorTexture", TestGltf.JSON.readTree("{\"index\": 0}"));
        ((ObjectNode) gltf.get("buffers").get(0)).put("byteLength", bin.length);
        GltfModel model = read(TestGltf.glb(gltf, bin));
        GltfTexture texture = model.parts().get(0).texture();
        assertArrayEquals(image, texture.image());
        assertEquals("image/png", texture.mediaType());
        assertEquals(List.of(), model.warnings()); // drawn where the part has UVs (GltfMappingTest)
    }

    @Test
    void aPrimitiveWithoutIndicesIsItsVerticesInOrder() {
        ObjectNode gltf = TestGltf.triangle();
        ((ObjectNode) gltf.get("meshes").get(0).get("primitives").get(0)).remove("indices");
        assertArrayEquals(new int[] {0, 1, 2}, read(TestGltf.bytes(gltf)).parts().get(0).mesh().indices());
        assertNull(read(TestGltf.bytes(gltf)).parts().get(0).uvs());
    }
}

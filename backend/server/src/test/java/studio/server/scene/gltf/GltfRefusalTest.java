package studio.server.scene.gltf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

import org.junit.jupiter.api.Test;

import tools.jackson.databind.node.ObjectNode;

import studio.engine.memory.MemoryGate;

/** Broken and hostile files: each is refused with a message naming the place, before anything large is allocated. */
class GltfRefusalTest {

    private static String refusal(byte[] bytes) {
        return assertThrows(IllegalArgumentException.class,
                () -> GltfReader.read(bytes, GltfAssets.none(), 1000, MemoryGate.UNLIMITED)).getMessage();
    }

    private static String refusal(ObjectNode gltf) {
        return refusal(TestGltf.bytes(gltf));
    }

    private static ObjectNode at(ObjectNode gltf, String array, int index) {
        return (ObjectNode) gltf.get(array).get(index);
    }

    @Test
    void refusesATruncatedGlb() {
        byte[] glb = TestGltf.glb(TestGltf.triangle(), TestGltf.triangleBuffer());
        assertEquals("its header declares " + glb.length + " bytes, but it has " + (glb.length - 10) + " (truncated)",
                refusal(Arrays.copyOf(glb, glb.length - 10)));
        assertTrue(refusal(Arrays.copyOf(glb, 7)).startsWith("it ends within its 12-byte header"));
    }

    @Test
    void refusesJsonThatDoesNotParseOrIsNotGltf2() {
        assertTrue(refusal("{\"asset\": {\"version\": \"2.0\"".getBytes(StandardCharsets.UTF_8))
                .startsWith("its JSON does not parse"));
        assertEquals("its JSON has no asset.version of \"2.0\"",
                refusal("{\"asset\": {\"version\": \"1.0\"}}".getBytes(StandardCharsets.UTF_8)));
    }

    @Test
    void refusesAnAccessorPastItsView() {
        ObjectNode gltf = TestGltf.triangle();
        at(gltf, "accessors", 0).put("count", 4);
        assertEquals("accessors[0]: its 4 elements run past the end of bufferViews[0] (48 > 36 bytes)", refusal(gltf));
        at(gltf, "accessors", 0).put("count", 3).put("byteOffset", 4);
        assertTrue(refusal(gltf).startsWith("accessors[0]: its 3 elements run past"));
    }

    @Test
    void refusesAViewPastItsBufferAndABufferLongerThanItsBytes() {
        ObjectNode gltf = TestGltf.triangle();
        at(gltf, "bufferViews", 1).put("byteOffset", 40);
        assertEquals("bufferViews[1]: its 6 bytes at offset 40 run past the end of buffers[0] (44 bytes)",
                refusal(gltf));
        gltf = TestGltf.triangle();
        at(gltf, "buffers", 0).put("byteLength", 4000);
        assertEquals("buffers[0]: declares 4000 bytes, but has 44", refusal(gltf));
    }

    @Test
    void refusesAnIndexPastTheVertices() {
        ObjectNode gltf = TestGltf.triangle();
        at(gltf, "accessors", 0).put("count", 2);
        assertEquals("accessors[1]: index 2 is 2, but the primitive has 2 vertices", refusal(gltf));
    }

    @Test
    void refusesReferencesToNothing() {
        ObjectNode gltf = TestGltf.triangle();
        at(gltf, "accessors", 1).put("bufferView", 7);
        assertEquals("accessors[1].bufferView: must name one of the 2 bufferViews (0 to 1)", refusal(gltf));
        gltf = TestGltf.triangle("[{\"mesh\": 3}]");
        assertEquals("nodes[0].mesh: must name one of the 1 meshes (0 to 0)", refusal(gltf));
    }

    @Test
    void refusesAWrongComponentTypeOrShape() {
        ObjectNode gltf = TestGltf.triangle();
        at(gltf, "accessors", 1).put("componentType", 5126);
        assertTrue(refusal(gltf).startsWith("accessors[1].componentType: 5126 is not allowed for indices"));
        gltf = TestGltf.triangle();
        at(gltf, "accessors", 0).put("type", "VEC2");
        assertTrue(refusal(gltf).startsWith("accessors[0].type: must be VEC3"));
    }

    @Test
    void refusesARequiredExtensionItLacks() {
        ObjectNode gltf = TestGltf.triangle();
        gltf.set("extensionsRequired", TestGltf.JSON.readTree("[\"KHR_draco_mesh_compression\"]"));
        assertEquals("extensionsRequired[0]: the file requires KHR_draco_mesh_compression, which is not supported",
                refusal(gltf));
    }

    @Test
    void refusesSparseAccessors() {
        ObjectNode gltf = TestGltf.triangle();
        at(gltf, "accessors", 0).set("sparse", TestGltf.JSON.readTree("{\"count\": 1}"));
        assertEquals("accessors[0].sparse: sparse accessors are not read", refusal(gltf));
    }

    @Test
    void neverFetchesAFileOrAUrl() {
        ObjectNode gltf = TestGltf.triangle();
        at(gltf, "buffers", 0).put("uri", "triangle.bin");
        assertTrue(refusal(gltf).startsWith("buffers[0].uri: only data: URIs and asset ids"));
        at(gltf, "buffers", 0).put("uri", "https://example.invalid/triangle.bin");
        assertTrue(refusal(gltf).startsWith("buffers[0].uri: only data: URIs and asset ids"));
    }

    @Test
    void namesAMissingBufferAsset() {
        ObjectNode gltf = TestGltf.triangle();
        String id = "sha256-" + "ab".repeat(32);
        at(gltf, "buffers", 0).put("uri", id);
        assertEquals("buffers[0].uri: this server has no asset " + id + "; upload it (POST /api/assets) first",
                refusal(gltf));
        byte[] buffer = TestGltf.triangleBuffer();
        GltfModel model = GltfReader.read(TestGltf.bytes(gltf), asked -> asked.equals(id) ? buffer : null, 1000,
                MemoryGate.UNLIMITED);
        assertEquals(1, model.triangleCount());
    }

    @Test
    void refusesNodesThatAreNotTrees() {
        assertEquals("nodes[0]: is reached twice; a node has at most one parent, and nodes form no cycle",
                refusal(TestGltf.triangle("[{\"children\": [0], \"mesh\": 0}]")));
        assertEquals("nodes[1]: is reached twice; a node has at most one parent, and nodes form no cycle",
                refusal(TestGltf.triangle("[{\"children\": [1, 1]}, {\"mesh\": 0}]")));
    }

    @Test
    void aDeepChainOfNodesDoesNotOverflowTheStack() {
        StringBuilder nodes = new StringBuilder("[");
        int depth = 100_000;
        for (int i = 0; i < depth - 1; i++) {
            nodes.append("{\"children\": [").append(i + 1).append("]},");
        }
        nodes.append("{\"mesh\": 0, \"translation\": [0, 0, 1]}]");
        assertEquals(1, GltfReaderTest.read(TestGltf.bytes(TestGltf.triangle(nodes.toString()))).triangleCount());
    }

    @Test
    void refusesMoreTrianglesThanTheLimitBeforeReadingThem() {
        ObjectNode gltf = TestGltf.triangle();
        StringBuilder nodes = new StringBuilder("[{\"children\": [");
        for (int i = 1; i <= 1001; i++) {
            nodes.append(i).append(i < 1001 ? "," : "]}");
        }
        for (int i = 1; i <= 1001; i++) {
            nodes.append(",{\"mesh\": 0}");
        }
        gltf.set("nodes", TestGltf.JSON.readTree(nodes + "]"));
        GltfReader.TooManyTrianglesException e = assertThrows(GltfReader.TooManyTrianglesException.class,
                () -> GltfReader.read(TestGltf.bytes(gltf), GltfAssets.none(), 1000, budget -> {
                    throw new AssertionError("nothing is allocated for a model past the limit");
                }));
        assertEquals(1001, e.triangles());
    }

    @Test
    void primitivesSharingALargeVertexBufferCostTheirTrianglesNotTheBuffer() {
        int vertices = 20_000;
        java.nio.ByteBuffer b = java.nio.ByteBuffer.allocate(12 * vertices + 8).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        for (int v = 0; v < vertices; v++) {
            b.putFloat(v).putFloat(v % 7).putFloat(0);
        }
        b.putShort((short) 5).putShort((short) 900).putShort((short) 19_999);
        StringBuilder primitives = new StringBuilder("[");
        for (int p = 0; p < 200; p++) {
            primitives.append(p > 0 ? "," : "").append("{\"attributes\": {\"POSITION\": 0}, \"indices\": 1}");
        }
        ObjectNode gltf = TestGltf.triangle();
        ((ObjectNode) gltf.get("meshes").get(0)).set("primitives", TestGltf.JSON.readTree(primitives + "]"));
        at(gltf, "accessors", 0).put("count", vertices);
        at(gltf, "bufferViews", 0).put("byteLength", 12 * vertices);
        at(gltf, "bufferViews", 1).put("byteOffset", 12 * vertices);
        at(gltf, "buffers", 0).put("byteLength", 12 * vertices + 8)
                .put("uri", "data:application/octet-stream;base64," + java.util.Base64.getEncoder().encodeToString(b.array()));
        long[] asked = {0};
        GltfModel model = GltfReader.read(TestGltf.bytes(gltf), GltfAssets.none(), 1000, bytes -> asked[0] += bytes);
        assertEquals(600, model.parts().get(0).mesh().vertexCount());
        assertEquals(200, model.triangleCount());
        // the buffer's 20,000 vertices read once (480,000 bytes as doubles), not once for each of the 200 primitives
        assertTrue(asked[0] < 1_000_000, () -> asked[0] + " bytes asked for");
        double[] p = model.parts().get(0).mesh().positions();
        assertEquals(19_999, p[3 * model.parts().get(0).mesh().indices()[5]], 0);
    }

    @Test
    void refusesMorePlacedPrimitivesThanTheLimitWhateverTheyDraw() {
        // 2,000 nodes on a mesh of 1,000 line primitives (no triangles): 2,000,000 primitives placed
        StringBuilder primitives = new StringBuilder("[");
        for (int p = 0; p < 1000; p++) {
            primitives.append(p > 0 ? "," : "").append("{\"attributes\": {\"POSITION\": 0}, \"mode\": 1}");
        }
        StringBuilder nodes = new StringBuilder("[{\"children\": [");
        for (int i = 1; i <= 2000; i++) {
            nodes.append(i).append(i < 2000 ? "," : "]}");
        }
        nodes.append(",{\"mesh\": 0}".repeat(2000)).append("]");
        ObjectNode gltf = TestGltf.triangle();
        ((ObjectNode) gltf.get("meshes").get(0)).set("primitives", TestGltf.JSON.readTree(primitives + "]"));
        gltf.set("nodes", TestGltf.JSON.readTree(nodes.toString()));
        assertEquals("nodes: they place 2000000 primitives; at most 1000 are read (as many as triangles)",
                refusal(gltf));
    }

    @Test
    void refusesNonFiniteTransformsAndProjections() {
        assertEquals("nodes[0].matrix: the matrix's last row must be (0, 0, 0, 1), not a projection",
                refusal(TestGltf.triangle("[{\"mesh\": 0, \"matrix\": [1,0,0,1, 0,1,0,0, 0,0,1,0, 0,0,0,1]}]")));
        assertEquals("scenes: the default scene draws no triangles",
                refusal(TestGltf.triangle("[{\"mesh\": 0, \"scale\": [1e300, 1e300, 1e300]}]")));
        assertEquals("nodes[0].rotation: translation, rotation and scale must be finite, the rotation non-zero",
                refusal(TestGltf.triangle("[{\"mesh\": 0, \"rotation\": [0, 0, 0, 0]}]")));
    }
}

package studio.server.asset;

import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;

import tools.jackson.databind.node.ObjectNode;

import studio.server.scene.gltf.TestGltf;

/** Small assets of each kind, well-formed or broken in one way, built byte by byte. */
final class AssetBytes {

    static final String TETRAHEDRON = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

    private AssetBytes() {
    }

    static byte[] obj() {
        return TETRAHEDRON.getBytes(StandardCharsets.UTF_8);
    }

    /** A fan of {@code triangles} triangles. */
    static byte[] fan(int triangles) {
        StringBuilder obj = new StringBuilder("v 0 0 0\n");
        for (int i = 0; i <= triangles; i++) {
            obj.append("v ").append(Math.cos(i * 0.01)).append(' ').append(Math.sin(i * 0.01)).append(" 0\n");
        }
        for (int i = 0; i < triangles; i++) {
            obj.append("f 1 ").append(i + 2).append(' ').append(i + 3).append('\n');
        }
        return obj.toString().getBytes(StandardCharsets.UTF_8);
    }

    /** A PNG's signature and IHDR declaring {@code width} x {@code height} (no image data follows: it is never decoded). */
    static byte[] png(int width, int height) {
        ByteBuffer b = ByteBuffer.allocate(33).order(ByteOrder.BIG_ENDIAN);
        b.put(AssetType.PNG_SIGNATURE).putInt(13).put("IHDR".getBytes(StandardCharsets.US_ASCII))
                .putInt(width).putInt(height).put(new byte[] {8, 2, 0, 0, 0}).putInt(0);
        return b.array();
    }

    /** A JPEG's start, an APP0 segment, and a baseline frame header declaring {@code width} x {@code height}. */
    static byte[] jpeg(int width, int height) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.writeBytes(new byte[] {(byte) 0xff, (byte) 0xd8});
        out.writeBytes(new byte[] {(byte) 0xff, (byte) 0xe0, 0, 6, 'J', 'F', 'I', 'F'});
        out.writeBytes(new byte[] {(byte) 0xff, (byte) 0xc0, 0, 11, 8, (byte) (height >> 8), (byte) height,
                (byte) (width >> 8), (byte) width, 1, 1, 0x11, 0});
        out.writeBytes(new byte[] {(byte) 0xff, (byte) 0xd9});
        return out.toByteArray();
    }

    /** A .gltf of one triangle, its buffer a data: URI. */
    static byte[] gltf() {
        return TestGltf.bytes(TestGltf.triangle());
    }

    /** A .gltf that places its one triangle {@code count} times, each under a node of its own. */
    static byte[] gltfOf(int count) {
        StringBuilder nodes = new StringBuilder("[{\"children\": [");
        for (int i = 1; i <= count; i++) {
            nodes.append(i).append(i < count ? "," : "]}");
        }
        nodes.append(",{\"mesh\": 0}".repeat(count)).append("]");
        return TestGltf.bytes(TestGltf.triangle(nodes.toString()));
    }

    /** The .gltf of one triangle whose positions' accessor claims a fourth vertex, past its buffer view. */
    static byte[] gltfPastItsView() {
        ObjectNode gltf = TestGltf.triangle();
        ((ObjectNode) gltf.get("accessors").get(0)).put("count", 4);
        return TestGltf.bytes(gltf);
    }

    /** A glb of one triangle: a JSON chunk (padded with spaces) and its BIN chunk. */
    static byte[] glb() {
        return TestGltf.glb(TestGltf.triangle(), TestGltf.triangleBuffer());
    }
}

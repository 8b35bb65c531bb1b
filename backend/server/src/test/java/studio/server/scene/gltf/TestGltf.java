package studio.server.scene.gltf;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.Base64;

import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.node.ObjectNode;

/**
 * glTF files written for tests: one red triangle (0,0,0), (1,0,0), (0,1,0) whose nodes a test sets,
 * as .gltf (its buffer a data: URI) or .glb (its buffer the BIN chunk); and the Khronos samples kept
 * under test resources gltf/khronos (each with its licence).
 */
public final class TestGltf {

    public static final JsonMapper JSON = JsonMapper.builder().build();

    private TestGltf() {
    }

    /** The triangle's buffer: three float positions, then three unsigned short indices and 2 bytes of padding. */
    public static byte[] triangleBuffer() {
        ByteBuffer b = ByteBuffer.allocate(44).order(ByteOrder.LITTLE_ENDIAN);
        for (float v : new float[] {0, 0, 0, 1, 0, 0, 0, 1, 0}) {
            b.putFloat(v);
        }
        b.putShort((short) 0).putShort((short) 1).putShort((short) 2);
        return b.array();
    }

    /** A .gltf of the triangle under {@code nodes} (JSON; the scene's root is node 0, the mesh is mesh 0). */
    public static ObjectNode triangle(String nodes) {
        String json = """
                {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": %s,
                 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
                 "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1], "metallicFactor": 0}}],
                 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                               {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
                 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                                 {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
                 "buffers": [{"byteLength": 44, "uri": "data:application/octet-stream;base64,%s"}]}
                """.formatted(nodes, Base64.getEncoder().encodeToString(triangleBuffer()));
        return (ObjectNode) JSON.readTree(json);
    }

    /** The triangle at the origin, as one node. */
    public static ObjectNode triangle() {
        return triangle("[{\"mesh\": 0}]");
    }

    public static byte[] bytes(ObjectNode gltf) {
        return JSON.writeValueAsString(gltf).getBytes(StandardCharsets.UTF_8);
    }

    /** A .glb of {@code gltf}'s JSON (its buffer 0's uri removed) with {@code bin} as its BIN chunk. */
    public static byte[] glb(ObjectNode gltf, byte[] bin) {
        ObjectNode json = gltf.deepCopy();
        ((ObjectNode) json.get("buffers").get(0)).remove("uri");
        byte[] text = JSON.writeValueAsString(json).getBytes(StandardCharsets.UTF_8);
        int jsonLength = (text.length + 3) / 4 * 4;
        int binLength = (bin.length + 3) / 4 * 4;
        ByteBuffer b = ByteBuffer.allocate(12 + 8 + jsonLength + 8 + binLength).order(ByteOrder.LITTLE_ENDIAN);
        b.putInt(0x46546C67).putInt(2).putInt(b.capacity());
        b.putInt(jsonLength).putInt(0x4E4F534A).put(text);
        for (int i = text.length; i < jsonLength; i++) {
            b.put((byte) ' ');
        }
        b.putInt(binLength).putInt(0x004E4942).put(bin);
        return b.array();
    }

    /** A Khronos sample from the test resources, e.g. "Box/Box.gltf". */
    public static byte[] khronos(String path) {
        try (InputStream in = TestGltf.class.getResourceAsStream("/gltf/khronos/" + path)) {
            return in.readAllBytes();
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }
}

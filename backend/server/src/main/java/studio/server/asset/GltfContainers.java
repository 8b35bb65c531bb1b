package studio.server.asset;

import tools.jackson.core.JacksonException;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * glTF 2.0 containers, checked but not yet read into a scene: a .glb's 12-byte header (magic
 * {@code glTF}, version 2, the declared length equal to the bytes' length) and its chunks (a JSON
 * chunk first, then at most one BIN chunk, each of a length that is a multiple of 4, filling the
 * file exactly); a .gltf's JSON (and a .glb's JSON chunk) must be an object whose
 * {@code asset.version} is "2.0".
 */
final class GltfContainers {

    private static final long JSON_CHUNK = 0x4E4F534AL; // "JSON", little-endian
    private static final long BIN_CHUNK = 0x004E4942L; // "BIN\0", little-endian
    private static final JsonMapper JSON = JsonMapper.builder().build();

    private GltfContainers() {
    }

    /** @throws IllegalArgumentException saying what is wrong with the container */
    static void glb(byte[] b) {
        if (b.length < 12) {
            throw new IllegalArgumentException("it ends within its 12-byte header (" + b.length + " bytes)");
        }
        long version = Bytes.littleEndianUnsignedInt(b, 4);
        long declared = Bytes.littleEndianUnsignedInt(b, 8);
        if (version != 2) {
            throw new IllegalArgumentException("its header declares glTF version " + version + "; only 2 is read");
        }
        if (declared != b.length) {
            throw new IllegalArgumentException("its header declares " + declared + " bytes, but " + b.length
                    + " were sent" + (declared > b.length ? " (truncated)" : ""));
        }
        int at = 12;
        int chunk = 0;
        while (at < b.length) {
            if (at + 8 > b.length) {
                throw new IllegalArgumentException("its chunk " + chunk + " ends within its 8-byte header");
            }
            long length = Bytes.littleEndianUnsignedInt(b, at);
            long type = Bytes.littleEndianUnsignedInt(b, at + 4);
            if (length % 4 != 0 || at + 8 + length > b.length) {
                throw new IllegalArgumentException("its chunk " + chunk + " declares " + length
                        + " bytes: not a multiple of 4, or past the end");
            }
            if (chunk == 0 && type != JSON_CHUNK) {
                throw new IllegalArgumentException("its first chunk is not JSON");
            }
            if (chunk == 1 && type != BIN_CHUNK || chunk > 1) {
                throw new IllegalArgumentException("its chunk " + chunk + " is not the one BIN chunk after the JSON");
            }
            if (chunk == 0) {
                json(b, at + 8, (int) length);
            }
            at += 8 + (int) length;
            chunk++;
        }
        if (chunk == 0) {
            throw new IllegalArgumentException("it has no JSON chunk");
        }
    }

    /** @throws IllegalArgumentException unless the bytes are a JSON object with asset.version "2.0" */
    static void gltf(byte[] b) {
        json(b, 0, b.length);
    }

    private static void json(byte[] b, int offset, int length) {
        JsonNode root;
        try {
            root = JSON.readTree(b, offset, length);
        } catch (JacksonException e) {
            throw new IllegalArgumentException("its JSON does not parse: " + e.getOriginalMessage());
        }
        if (root == null || !root.isObject()) {
            throw new IllegalArgumentException("its JSON is not an object");
        }
        JsonNode version = root.path("asset").path("version");
        if (!version.isString() || !"2.0".equals(version.asString())) {
            throw new IllegalArgumentException("its JSON has no asset.version of \"2.0\"");
        }
    }
}

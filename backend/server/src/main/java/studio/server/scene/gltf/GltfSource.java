package studio.server.scene.gltf;

import tools.jackson.core.JacksonException;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * A glTF file's JSON and, for a .glb, its BIN chunk. A .glb is checked as it is split: its 12-byte
 * header (magic {@code glTF}, version 2, the declared length equal to the bytes' length), a JSON chunk
 * first, then at most one BIN chunk, each of a length that is a multiple of 4, filling the file
 * exactly. The JSON must be an object whose {@code asset.version} is "2.0".
 *
 * @param bin the BIN chunk, or null
 */
record GltfSource(JsonNode root, Slice bin) {

    private static final long MAGIC = 0x46546C67L; // "glTF", little-endian
    private static final long JSON_CHUNK = 0x4E4F534AL; // "JSON"
    private static final long BIN_CHUNK = 0x004E4942L; // "BIN\0"
    private static final JsonMapper JSON = JsonMapper.builder().build();

    /** A .glb if the bytes start with its magic, else a .gltf's JSON. */
    static GltfSource of(byte[] bytes) {
        Slice all = Slice.of(bytes);
        return bytes.length >= 4 && all.u32(0) == MAGIC ? glb(all) : new GltfSource(json(all), null);
    }

    private static GltfSource glb(Slice b) {
        if (b.length() < 12) {
            throw new IllegalArgumentException("it ends within its 12-byte header (" + b.length() + " bytes)");
        }
        long version = b.u32(4);
        long declared = b.u32(8);
        if (version != 2) {
            throw new IllegalArgumentException("its header declares glTF version " + version + "; only 2 is read");
        }
        if (declared != b.length()) {
            throw new IllegalArgumentException("its header declares " + declared + " bytes, but it has " + b.length()
                    + (declared > b.length() ? " (truncated)" : ""));
        }
        JsonNode root = null;
        Slice bin = null;
        long at = 12;
        int chunk = 0;
        while (at < b.length()) {
            if (at + 8 > b.length()) {
                throw new IllegalArgumentException("its chunk " + chunk + " ends within its 8-byte header");
            }
            long length = b.u32(at);
            long type = b.u32(at + 4);
            if (length % 4 != 0 || at + 8 + length > b.length()) {
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
                root = json(b.sub(at + 8, length));
            } else {
                bin = b.sub(at + 8, length);
            }
            at += 8 + length;
            chunk++;
        }
        if (root == null) {
            throw new IllegalArgumentException("it has no JSON chunk");
        }
        return new GltfSource(root, bin);
    }

    private static JsonNode json(Slice s) {
        JsonNode root;
        try {
            root = JSON.readTree(s.bytes(), s.offset(), s.length());
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
        return root;
    }
}

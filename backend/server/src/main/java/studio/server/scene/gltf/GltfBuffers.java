package studio.server.scene.gltf;

import static studio.server.scene.gltf.GltfJson.bad;

import java.util.Base64;
import java.util.regex.Pattern;

import tools.jackson.databind.JsonNode;

/**
 * A glTF's buffers and buffer views, each read when first needed and checked to lie within the bytes
 * that are there. A buffer is the glb's BIN chunk (no {@code uri}), a base64 {@code data:} URI, or
 * another asset named by its id ({@code "uri": "sha256-..."}); a relative file or a URL is refused,
 * never fetched.
 */
final class GltfBuffers {

    private static final Pattern ASSET_ID = Pattern.compile("sha256-[0-9a-f]{64}");

    private final JsonNode buffers;
    private final JsonNode views;
    private final Slice bin;
    private final GltfAssets assets;
    private final Slice[] read;

    GltfBuffers(JsonNode root, Slice bin, GltfAssets assets) {
        this.buffers = GltfJson.array(root, "buffers", "");
        this.views = GltfJson.array(root, "bufferViews", "");
        this.bin = bin;
        this.assets = assets;
        this.read = new Slice[buffers.size()];
    }

    int viewCount() {
        return views.size();
    }

    /** The bytes of buffer view {@code i}. */
    Slice view(int i) {
        String path = "bufferViews[" + i + "]";
        JsonNode view = GltfJson.element(views, i, "bufferViews");
        int b = GltfJson.index(view, "buffer", buffers.size(), "buffers", path);
        Slice buffer = buffer(b);
        long offset = GltfJson.whole(view, "byteOffset", 0, Integer.MAX_VALUE, 0, path);
        long length = GltfJson.whole(view, "byteLength", 1, Integer.MAX_VALUE, -1, path);
        if (length < 0) {
            throw bad(path + ".byteLength", "is required");
        }
        if (offset + length > buffer.length()) {
            throw bad(path, "its " + length + " bytes at offset " + offset + " run past the end of buffers[" + b
                    + "] (" + buffer.length() + " bytes)");
        }
        return buffer.sub(offset, length);
    }

    /** The byte stride of buffer view {@code i}, or 0 if its elements are tightly packed. */
    int stride(int i) {
        JsonNode view = GltfJson.element(views, i, "bufferViews");
        long stride = GltfJson.whole(view, "byteStride", 4, 252, 0, "bufferViews[" + i + "]");
        if (stride % 4 != 0) {
            throw bad("bufferViews[" + i + "].byteStride", "must be a multiple of 4");
        }
        return (int) stride;
    }

    private Slice buffer(int i) {
        if (read[i] == null) {
            read[i] = load(i);
        }
        return read[i];
    }

    private Slice load(int i) {
        String path = "buffers[" + i + "]";
        JsonNode buffer = GltfJson.element(buffers, i, "buffers");
        long length = GltfJson.whole(buffer, "byteLength", 1, Integer.MAX_VALUE, -1, path);
        if (length < 0) {
            throw bad(path + ".byteLength", "is required");
        }
        String uri = GltfJson.string(buffer, "uri", path);
        Slice bytes;
        if (uri == null) {
            if (bin == null || i != 0) {
                throw bad(path, "has no uri, and only a .glb's first buffer may be its BIN chunk");
            }
            bytes = bin;
        } else {
            bytes = Slice.of(uriBytes(uri, path + ".uri", assets));
        }
        if (bytes.length() < length) {
            throw bad(path, "declares " + length + " bytes, but has " + bytes.length());
        }
        return bytes.sub(0, length);
    }

    /** The bytes a buffer's or an image's {@code uri} names: a base64 data: URI or an asset id. */
    static byte[] uriBytes(String uri, String path, GltfAssets assets) {
        if (uri.startsWith("data:")) {
            int comma = uri.indexOf(',');
            if (comma < 0 || !uri.substring(0, comma).endsWith(";base64")) {
                throw bad(path, "a data: URI must be base64 (data:<type>;base64,...)");
            }
            try {
                return Base64.getDecoder().decode(uri.substring(comma + 1));
            } catch (IllegalArgumentException e) {
                throw bad(path, "its base64 does not decode: " + e.getMessage());
            }
        }
        if (ASSET_ID.matcher(uri).matches()) {
            byte[] bytes = assets.bytes(uri);
            if (bytes == null) {
                throw bad(path, "this server has no asset " + uri + "; upload it (POST /api/assets) first");
            }
            return bytes;
        }
        throw bad(path, "only data: URIs and asset ids (sha256-...) are read, never a file or a URL: embed it, "
                + "or upload it as an asset and name its id");
    }
}

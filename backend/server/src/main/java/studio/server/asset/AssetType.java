package studio.server.asset;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Locale;

/**
 * The kinds of asset this server keeps, by media type, and what a kind's bytes start with: how a
 * media type that lies (PNG bytes sent as image/jpeg, JSON as model/gltf-binary) is caught before
 * the bytes are read as what they claim to be.
 */
public enum AssetType {
    OBJ("model/obj", "OBJ text"),
    PNG("image/png", "a PNG image"),
    JPEG("image/jpeg", "a JPEG image"),
    GLB("model/gltf-binary", "a binary glTF (glb)"),
    GLTF("model/gltf+json", "JSON (glTF)"),
    /** Any bytes: a .gltf's buffer (a .bin file), which the .gltf names by its id. */
    BIN("application/octet-stream", "binary data");

    static final byte[] PNG_SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static final byte[] GLB_MAGIC = "glTF".getBytes(StandardCharsets.US_ASCII);

    private final String mediaType;
    private final String looksLike;

    AssetType(String mediaType, String looksLike) {
        this.mediaType = mediaType;
        this.looksLike = looksLike;
    }

    public String mediaType() {
        return mediaType;
    }

    /** What bytes of this kind look like, in words ("a PNG image"). */
    String looksLike() {
        return looksLike;
    }

    /** The kind a Content-Type names (its parameters, such as a charset, aside), or null if none. */
    public static AssetType ofMediaType(String contentType) {
        if (contentType == null) {
            return null;
        }
        String type = contentType.split(";", 2)[0].trim().toLowerCase(Locale.ROOT);
        return Arrays.stream(values()).filter(t -> t.mediaType.equals(type)).findFirst().orElse(null);
    }

    /** The kind the bytes look like by their first bytes; text that is not JSON looks like OBJ. */
    static AssetType sniff(byte[] bytes) {
        if (startsWith(bytes, PNG_SIGNATURE)) {
            return PNG;
        }
        if (bytes.length >= 3 && (bytes[0] & 0xff) == 0xff && (bytes[1] & 0xff) == 0xd8 && (bytes[2] & 0xff) == 0xff) {
            return JPEG;
        }
        if (startsWith(bytes, GLB_MAGIC)) {
            return GLB;
        }
        for (byte b : bytes) {
            if (b != ' ' && b != '\t' && b != '\r' && b != '\n') {
                return b == '{' || b == '[' ? GLTF : OBJ;
            }
        }
        return OBJ;
    }

    private static boolean startsWith(byte[] bytes, byte[] prefix) {
        return bytes.length >= prefix.length && Arrays.equals(bytes, 0, prefix.length, prefix, 0, prefix.length);
    }
}

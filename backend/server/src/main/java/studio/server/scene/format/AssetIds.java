package studio.server.scene.format;

import java.util.regex.Pattern;

/**
 * How a scene names an asset (bytes stored on the server by POST /api/assets): {@code sha256-} and
 * the 64 lowercase hex digits of the SHA-256 of its bytes. Part of the format (the schema publishes
 * the rule); the asset feature computes such ids and keeps the bytes.
 */
public final class AssetIds {

    public static final String PREFIX = "sha256-";
    public static final String RULE = "sha256-[0-9a-f]{64}";
    public static final String MESSAGE = "must be an asset id: \"sha256-\" and 64 lowercase hex digits";
    public static final Pattern PATTERN = Pattern.compile(RULE);

    private AssetIds() {
    }

    public static boolean isValid(String id) {
        return id != null && PATTERN.matcher(id).matches();
    }
}

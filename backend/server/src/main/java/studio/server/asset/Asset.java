package studio.server.asset;

/**
 * Bytes kept by their content's hash, with the media type they were checked as.
 *
 * @param id    {@code sha256-} and the hex SHA-256 of {@code bytes}
 * @param bytes never changed once kept (shared, not copied)
 */
public record Asset(String id, AssetType type, byte[] bytes) {

    /** The bytes with their id computed. */
    public static Asset of(AssetType type, byte[] bytes) {
        return new Asset(AssetIds.of(bytes), type, bytes);
    }
}

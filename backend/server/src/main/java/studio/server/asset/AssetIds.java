package studio.server.asset;

import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;

/** An asset's id: {@code sha256-} and the lowercase hex SHA-256 of its bytes (the rule is the scene format's). */
final class AssetIds {

    private AssetIds() {
    }

    static String of(byte[] bytes) {
        try {
            return studio.server.scene.format.AssetIds.PREFIX
                    + HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java runtime has SHA-256", e);
        }
    }

    /** @throws AssetRefusedException (400) unless {@code id} has the form of an asset id */
    static String require(String id) {
        if (!studio.server.scene.format.AssetIds.isValid(id)) {
            throw AssetRefusedException.badId();
        }
        return id;
    }
}

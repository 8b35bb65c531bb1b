package studio.server.security;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.List;

/**
 * The API keys of {@code studio.security.api-keys} (NAME:KEY,NAME:KEY), held as SHA-256 digests and
 * compared in constant time: how long a lookup takes says nothing about how much of a key was right.
 */
final class ApiKeys {

    private record Key(String name, byte[] digest) {
    }

    private final List<Key> keys;

    private ApiKeys(List<Key> keys) {
        this.keys = List.copyOf(keys);
    }

    /**
     * Reads NAME:KEY pairs, comma-separated; blank means none.
     *
     * @throws IllegalArgumentException naming the entry (by position, never by its key) that is not NAME:KEY,
     *                                  or a key given twice
     */
    static ApiKeys parse(String text) {
        List<Key> keys = new ArrayList<>();
        if (text == null || text.isBlank()) {
            return new ApiKeys(keys);
        }
        String[] entries = text.split(",");
        for (int i = 0; i < entries.length; i++) {
            String entry = entries[i].trim();
            int colon = entry.indexOf(':');
            if (colon <= 0 || colon == entry.length() - 1) {
                throw new IllegalArgumentException("studio.security.api-keys: entry " + (i + 1)
                        + " is not NAME:KEY (both non-empty)");
            }
            byte[] digest = digest(entry.substring(colon + 1).trim());
            for (Key known : keys) {
                if (MessageDigest.isEqual(known.digest(), digest)) {
                    throw new IllegalArgumentException("studio.security.api-keys: entry " + (i + 1)
                            + " repeats the key of " + known.name() + "; give each a key of its own");
                }
            }
            keys.add(new Key(entry.substring(0, colon).trim(), digest));
        }
        return new ApiKeys(keys);
    }

    int size() {
        return keys.size();
    }

    /** The name of the key presented, or null if it is none of them; every key is compared, whatever matches. */
    String principal(String presented) {
        byte[] digest = digest(presented);
        String found = null;
        for (Key key : keys) {
            if (MessageDigest.isEqual(key.digest(), digest) && found == null) {
                found = key.name();
            }
        }
        return found;
    }

    private static byte[] digest(String key) {
        try {
            return MessageDigest.getInstance("SHA-256").digest(key.getBytes(StandardCharsets.UTF_8));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java platform has SHA-256", e);
        }
    }
}

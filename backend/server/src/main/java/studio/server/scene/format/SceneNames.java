package studio.server.scene.format;

import java.text.Normalizer;

/** Turns a scene's free-text name into a safe file name stem: no path, no quotes, no control characters. */
public final class SceneNames {

    private static final int MAX_LENGTH = 100;

    private SceneNames() {
    }

    /**
     * Letters, digits, '-' and '_' survive (accents are stripped); every other run of characters
     * becomes one '-'. An empty result becomes "render". "../../etc/passwd" gives "etc-passwd".
     */
    public static String toFileStem(String name) {
        if (name == null) {
            return SceneDefaults.NAME;
        }
        String ascii = Normalizer.normalize(name, Normalizer.Form.NFD).replaceAll("\\p{M}+", "");
        String stem = ascii.replaceAll("[^A-Za-z0-9_-]+", "-").replaceAll("^[-_]+|[-_]+$", "");
        if (stem.length() > MAX_LENGTH) {
            stem = stem.substring(0, MAX_LENGTH).replaceAll("[-_]+$", "");
        }
        return stem.isEmpty() ? SceneDefaults.NAME : stem;
    }
}

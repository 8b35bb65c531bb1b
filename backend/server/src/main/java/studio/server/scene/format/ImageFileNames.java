package studio.server.scene.format;

import java.util.regex.Pattern;

/** The rule for an image texture's {@code file} name: as {@link MeshFileNames}, ending in .png, .jpg or .jpeg. */
public final class ImageFileNames {

    public static final String RULE = "(?!.*\\.\\.)(?!.*/\\.)(?!.*//)[A-Za-z0-9_-][A-Za-z0-9._/-]*\\.(png|jpg|jpeg)";
    public static final String MESSAGE = "must be a relative path of letters, digits, '.', '_', '-' and '/' ending in "
            + ".png, .jpg or .jpeg, without \"..\"";
    public static final Pattern PATTERN = Pattern.compile(RULE);

    private ImageFileNames() {
    }
}

package studio.server.scene.format;

import java.util.regex.Pattern;

/**
 * The rule for a glTF object's {@code file} name: as a mesh's ({@link MeshFileNames}), ending in .glb
 * or .gltf. Part of the format (the schema publishes it); where such a file is read from is the
 * compiler's business (MeshFiles).
 */
public final class GltfFileNames {

    public static final String RULE = "(?!.*\\.\\.)(?!.*/\\.)(?!.*//)[A-Za-z0-9_-][A-Za-z0-9._/-]*\\.(glb|gltf)";
    public static final String MESSAGE = "must be a relative path of letters, digits, '.', '_', '-' and '/' ending in "
            + ".glb or .gltf, without \"..\"";
    public static final Pattern PATTERN = Pattern.compile(RULE);

    private GltfFileNames() {
    }
}

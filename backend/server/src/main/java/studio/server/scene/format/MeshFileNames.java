package studio.server.scene.format;

import java.util.regex.Pattern;

/**
 * The rule for a mesh's {@code file} name: a relative name of folders and a file ending in .obj; no
 * "..", no absolute paths, no backslashes; every folder and the file start with a letter, digit, '_'
 * or '-' (no "/." and no "//"). Part of the format (the schema publishes it); where such a file is
 * read from is the compiler's business (MeshFiles).
 */
public final class MeshFileNames {

    /**
     * The rule as a regular expression for the whole name, as Bean Validation's @Pattern and JSON
     * Schema use it, without a repeated group: Java matches one by recursion, and a name of 10,000
     * folders overflowed the stack.
     */
    public static final String RULE = "(?!.*\\.\\.)(?!.*/\\.)(?!.*//)[A-Za-z0-9_-][A-Za-z0-9._/-]*\\.obj";
    public static final String MESSAGE = "must be a relative path of letters, digits, '.', '_', '-' and '/' ending in .obj, without \"..\"";
    public static final Pattern PATTERN = Pattern.compile(RULE);

    private MeshFileNames() {
    }
}

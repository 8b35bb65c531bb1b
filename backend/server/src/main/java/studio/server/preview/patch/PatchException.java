package studio.server.preview.patch;

/**
 * A JSON Patch that cannot be read or does not apply, naming the field at fault by its path in the
 * patch ({@code patch[2].path}) and saying why.
 */
public final class PatchException extends RuntimeException {

    private final String field;

    public PatchException(String field, String message) {
        super(message);
        this.field = field;
    }

    /** The field at fault: {@code patch}, or {@code patch[i]} and one of its members. */
    public String field() {
        return field;
    }
}

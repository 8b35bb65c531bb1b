package studio.engine.mesh;

/**
 * OBJ text with more triangles than its reader may read. It is thrown as soon as a face passes the
 * limit, so the rest of the text is never read and no array grows beyond the limit.
 */
public final class TooManyTrianglesException extends IllegalArgumentException {

    private final int limit;
    private final int line;

    public TooManyTrianglesException(int limit, int line) {
        super("OBJ line " + line + ": more than " + limit + " triangles");
        this.limit = limit;
        this.line = line;
    }

    /** The most triangles the reader was allowed. */
    public int limit() {
        return limit;
    }

    /** The 1-based line where the limit was passed. */
    public int line() {
        return line;
    }
}

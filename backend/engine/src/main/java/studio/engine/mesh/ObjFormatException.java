package studio.engine.mesh;

/** Wavefront OBJ text that cannot be read as a mesh; the message starts with the line number. */
public final class ObjFormatException extends IllegalArgumentException {

    private final int line;

    public ObjFormatException(int line, String problem) {
        super("OBJ line " + line + ": " + problem);
        this.line = line;
    }

    /** The 1-based line where the problem is. */
    public int line() {
        return line;
    }
}

package studio.server.system;

/**
 * The heap a JSON request body takes once it has been read and parsed into a scene, reckoned from
 * its bytes as they arrive: {@value #BYTES_PER_BYTE} bytes for each byte, and for each character
 * that makes the parser build something more: <code>{</code> {@value #PER_OBJECT} (an object
 * node with its map, a record), <code>[</code> {@value #PER_ARRAY} (an array node, a list),
 * <code>,</code> {@value #PER_ELEMENT} (another member or element: its node, boxed number or
 * string) and <code>:</code> {@value #PER_MEMBER} (a map entry). Such characters inside strings
 * count too, which only overestimates.
 *
 * <p>The figures bound what was measured: the smallest heap (G1) in which a 33 MB body of one
 * shape, repeated, was read into a scene, less the JVM's 11 MiB, per repeat, with the body's bytes
 * counted twice, as they are held while the body is assembled. Text: 6.2 bytes a byte (an OBJ mesh
 * inline, a long name). <code>1,</code> 37 bytes (reckoned 80); <code>"a",</code> 81 (96);
 * <code>{},</code> 110 (248); <code>{"a":1},</code> 235 (320);
 * <code>{"type":"sphere"},</code> 331 (400); <code>[[[[1]]]],</code> 435 (528);
 * <code>"k123456":1,</code> 148 (196). These are compressed references (heaps under 32 GB); above,
 * nodes grow by up to half, which the other half of such a heap absorbs. What the scene's meshes
 * take once their OBJ text is parsed, the engine asks for itself.
 */
final class BodyMemory {

    static final int BYTES_PER_BYTE = 8;
    static final int PER_OBJECT = 160;
    static final int PER_ARRAY = 96;
    static final int PER_ELEMENT = 64;
    static final int PER_MEMBER = 32;

    private static final int[] EXTRA = new int[256];

    static {
        EXTRA['{'] = PER_OBJECT;
        EXTRA['['] = PER_ARRAY;
        EXTRA[','] = PER_ELEMENT;
        EXTRA[':'] = PER_MEMBER;
    }

    private BodyMemory() {
    }

    /** The heap {@code length} bytes of JSON from {@code offset} will take. */
    static long of(byte[] buffer, int offset, int length) {
        long extra = 0;
        for (int i = offset, end = offset + length; i < end; i++) {
            extra += EXTRA[buffer[i] & 0xff];
        }
        return (long) BYTES_PER_BYTE * length + extra;
    }
}

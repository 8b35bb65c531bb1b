package studio.engine.memory;

/**
 * Asked before the engine allocates memory that grows with its input: the arrays an OBJ text is
 * read into, a mesh's world-space copies, its BVH and its light buffers. Whoever runs the engine
 * can so refuse work its heap cannot hold before the heap runs out (the server draws on its memory
 * budget; the command line grants everything). A gate refuses by throwing an exception of its own, which the engine
 * passes on, allocating nothing more for that work.
 *
 * <p>What is granted stays counted until the work ends: an array that a growth or a copy replaces
 * is not given back, so the total bounds what the work holds at its peak (doubling growth counts at
 * most twice the final size).
 */
@FunctionalInterface
public interface MemoryGate {

    /** Grants everything (the command line, tests, benchmarks). */
    MemoryGate UNLIMITED = bytes -> { };

    /** Asks for {@code bytes} more before they are allocated; throws to refuse. */
    void reserve(long bytes);

    /**
     * Asks for {@code bytes} more that the work can do without (a speed-up's arrays, such as a
     * mesh's light buffers): true if granted; false, granting nothing, where {@link #reserve} would
     * refuse or wait, so the work goes on without them. By default through {@link #reserve}, which
     * suits a gate that grants everything.
     */
    default boolean tryReserve(long bytes) {
        reserve(bytes);
        return true;
    }

    /** The heap an array of {@code length} doubles takes (a 16-byte header and the elements). */
    static long doubles(long length) {
        return 16 + 8 * length;
    }

    /** The heap an array of {@code length} ints takes. */
    static long ints(long length) {
        return 16 + 4 * length;
    }

    /** The heap an array of {@code length} floats takes. */
    static long floats(long length) {
        return 16 + 4 * length;
    }

    /** The heap an array of {@code length} longs takes. */
    static long longs(long length) {
        return 16 + 8 * length;
    }

    /** The heap an array of {@code length} chars takes. */
    static long chars(long length) {
        return 16 + 2 * length;
    }
}

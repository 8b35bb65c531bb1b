package studio.server.system;

import java.util.concurrent.atomic.AtomicBoolean;

/**
 * The heap the service lets requests hold at once, in bytes. Work that needs memory (reading a
 * request body into a scene, a render's film and image, a finished job's image) reserves its
 * estimate first and is refused when the rest of the budget cannot cover it, so no request can
 * drive the JVM out of memory; the client is told to retry (503 or 429 with Retry-After) or, when
 * the work could never fit, why (400).
 */
public final class MemoryBudget {

    private final long capacity;
    private long reserved;

    public MemoryBudget(long capacity) {
        if (capacity <= 0) {
            throw new IllegalArgumentException("the memory budget must be positive: " + capacity);
        }
        this.capacity = capacity;
    }

    /** A share of the JVM's maximum heap ({@code -Xmx}). */
    public static MemoryBudget ofHeapShare(double share) {
        if (!(share > 0 && share <= 1)) {
            throw new IllegalArgumentException("the heap share must be in (0, 1]: " + share);
        }
        return new MemoryBudget((long) (Runtime.getRuntime().maxMemory() * share));
    }

    /** Effectively no limit (the command line, tests). */
    public static MemoryBudget unlimited() {
        return new MemoryBudget(Long.MAX_VALUE);
    }

    public long capacity() {
        return capacity;
    }

    public synchronized long reserved() {
        return reserved;
    }

    /** Reserves {@code bytes} if they are free now; null if not. Close the reservation to give them back. */
    public synchronized Reservation tryReserve(long bytes) {
        if (bytes < 0) {
            throw new IllegalArgumentException("cannot reserve a negative amount: " + bytes);
        }
        if (bytes > capacity - reserved) {
            return null;
        }
        reserved += bytes;
        return new Reservation(bytes);
    }

    /**
     * Counts {@code bytes} that are already allocated (a finished image), even beyond the budget:
     * new work waits until they are given back.
     */
    public synchronized Reservation forceReserve(long bytes) {
        if (bytes < 0) {
            throw new IllegalArgumentException("cannot reserve a negative amount: " + bytes);
        }
        reserved += bytes;
        return new Reservation(bytes);
    }

    private synchronized void release(long bytes) {
        reserved -= bytes;
    }

    /** Bytes held until {@link #close()}; closing twice gives them back once. */
    public final class Reservation implements AutoCloseable {
        private final long bytes;
        private final AtomicBoolean closed = new AtomicBoolean();

        private Reservation(long bytes) {
            this.bytes = bytes;
        }

        public long bytes() {
            return bytes;
        }

        @Override
        public void close() {
            if (closed.compareAndSet(false, true)) {
                release(bytes);
            }
        }
    }
}

package studio.server.system;

import java.time.Duration;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * The heap the service lets requests hold at once, in bytes. Work that needs memory (reading a
 * request body into a scene, a render's film and image, a finished job's image) reserves its
 * estimate first and is refused when the rest of the budget cannot cover it, so no request can
 * drive the JVM out of memory; the client is told to retry (503 or 429 with Retry-After) or, when
 * the work could never fit, why (400 or 413).
 *
 * <p>A reservation may grow as its work goes on (a request body as it arrives, then its scene as it
 * is compiled: {@link IntakeMemory}) and may hand its memory over to the work that follows (the
 * compiled scene's render) in one step, so that memory passing between them is neither counted
 * twice nor left uncounted for a moment.
 *
 * <p>One growing reservation at a time may wait for memory to come free ({@link
 * Reservation#growOrWait}); while it waits, other work takes only what leaves its need free, and
 * other reservations that cannot grow are refused at once. So a burst of large request bodies ends
 * with one of them read and the others told to retry, instead of each holding part of the memory
 * and all of them refused.
 *
 * <p>What is only kept to save work later (a live view's last scene and film) holds a
 * <em>yielding</em> reservation ({@link #tryReserveYielding}): when other work finds the memory
 * short, the budget takes those back, oldest first, each holder told to drop what it kept, before
 * it refuses anyone.
 */
public final class MemoryBudget {

    private final long capacity;
    private long reserved;
    /** The reservation waiting to grow, and by how much; null if none waits. */
    private Reservation waiter;
    private long waiterNeeds;
    /** The yielding reservations, oldest first, with what tells each holder to drop what it keeps. */
    private final Map<Reservation, Runnable> yielding = new LinkedHashMap<>();

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

    /** What {@code asker} may take now: the rest of the budget, less what another, waiting reservation needs. */
    private long freeFor(Reservation asker) {
        return capacity - reserved - (waiter != null && waiter != asker ? waiterNeeds : 0);
    }

    /**
     * Reserves {@code bytes} if they are free now; null if not (nothing, 0 bytes, is always free).
     * Close the reservation to give them back.
     */
    public synchronized Reservation tryReserve(long bytes) {
        if (bytes < 0) {
            throw new IllegalArgumentException("cannot reserve a negative amount: " + bytes);
        }
        if (bytes > 0 && !makeRoom(bytes, null)) {
            return null;
        }
        reserved += bytes;
        return new Reservation(bytes);
    }

    /**
     * Reserves {@code bytes} for something only kept to save work later, if they are free now
     * (without taking other yielding reservations back); null if not. When other work finds the
     * memory short, the budget runs {@code giveBack} (on that work's thread, holding the budget's
     * lock: it must only drop what it keeps, and may close the reservation) and closes the
     * reservation.
     */
    public synchronized Reservation tryReserveYielding(long bytes, Runnable giveBack) {
        if (bytes < 0) {
            throw new IllegalArgumentException("cannot reserve a negative amount: " + bytes);
        }
        if (bytes > 0 && bytes > freeFor(null)) {
            return null;
        }
        reserved += bytes;
        Reservation reservation = new Reservation(bytes);
        yielding.put(reservation, giveBack);
        return reservation;
    }

    /** How many yielding reservations are held (studio_render_memory_kept in the metrics). */
    public synchronized int yieldingCount() {
        return yielding.size();
    }

    /**
     * Takes yielding reservations back, oldest first, until {@code needed} bytes are free for
     * {@code asker} or none is left; whether they are free.
     */
    private boolean makeRoom(long needed, Reservation asker) {
        Iterator<Map.Entry<Reservation, Runnable>> oldest = yielding.entrySet().iterator();
        while (needed > freeFor(asker) && oldest.hasNext()) {
            Map.Entry<Reservation, Runnable> taken = oldest.next();
            oldest.remove();
            taken.getValue().run();
            taken.getKey().close();
            oldest = yielding.entrySet().iterator(); // giveBack may have closed others
        }
        return needed <= freeFor(asker);
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

    /** Bytes held until {@link #close()}; closing twice gives them back once. Guarded by the budget. */
    public final class Reservation implements AutoCloseable {
        private long bytes;
        private boolean closed;

        private Reservation(long bytes) {
            this.bytes = bytes;
        }

        public long bytes() {
            synchronized (MemoryBudget.this) {
                return bytes;
            }
        }

        /** Holds {@code more} bytes besides, if they are free now; false, holding what it held, if not. */
        public boolean tryGrow(long more) {
            if (more < 0) {
                throw new IllegalArgumentException("cannot grow by a negative amount: " + more);
            }
            synchronized (MemoryBudget.this) {
                if (closed) {
                    throw new IllegalStateException("the reservation was given back");
                }
                if (!makeRoom(more, this)) {
                    return false;
                }
                reserved += more;
                bytes += more;
                return true;
            }
        }

        /**
         * Holds {@code more} bytes besides, waiting up to {@code bound} for them to come free, if no
         * other reservation is waiting and the whole budget could hold this one grown.
         *
         * @return false, holding what it held, if another waits, this could never fit, or the bound passed
         */
        public boolean growOrWait(long more, Duration bound) {
            if (more < 0) {
                throw new IllegalArgumentException("cannot grow by a negative amount: " + more);
            }
            synchronized (MemoryBudget.this) {
                if (closed) {
                    throw new IllegalStateException("the reservation was given back");
                }
                if (waiter != null || more > capacity - bytes) {
                    return false;
                }
                waiter = this;
                waiterNeeds = more;
                try {
                    long deadline = System.nanoTime() + bound.toNanos();
                    makeRoom(more, this);
                    while (more > capacity - reserved) {
                        long left = deadline - System.nanoTime();
                        if (left <= 0) {
                            return false;
                        }
                        TimeUnit.NANOSECONDS.timedWait(MemoryBudget.this, left);
                    }
                    reserved += more;
                    bytes += more;
                    return true;
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return false;
                } finally {
                    waiter = null;
                    waiterNeeds = 0;
                }
            }
        }

        /**
         * Reserves {@code next} bytes for the work this one passes its memory on to, in the same step
         * in which this reservation shrinks to {@code keep} (or what it holds, if less).
         *
         * @return the new reservation, or null, this one unchanged, if the budget cannot cover it
         */
        public Reservation tryHandOver(long next, long keep) {
            if (next < 0 || keep < 0) {
                throw new IllegalArgumentException("cannot reserve a negative amount: " + next + ", " + keep);
            }
            synchronized (MemoryBudget.this) {
                if (closed) {
                    throw new IllegalStateException("the reservation was given back");
                }
                long freed = bytes - Math.min(keep, bytes);
                if (!makeRoom(next - freed, this)) {
                    return null;
                }
                bytes -= freed;
                reserved += next - freed;
                MemoryBudget.this.notifyAll();
                return new Reservation(next);
            }
        }

        @Override
        public void close() {
            synchronized (MemoryBudget.this) {
                if (!closed) {
                    closed = true;
                    yielding.remove(this);
                    reserved -= bytes;
                    MemoryBudget.this.notifyAll();
                }
            }
        }
    }
}

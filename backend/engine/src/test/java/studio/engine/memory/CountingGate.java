package studio.engine.memory;

import java.lang.management.ManagementFactory;

/**
 * A gate for tests: it grants up to a limit, counts what it granted, and refuses beyond with
 * {@link Refused}; {@link #allocatedBy} measures what the current thread allocates meanwhile, so a
 * test can check that what the engine allocates was asked for first.
 */
public final class CountingGate implements MemoryGate {

    /** What a test may allocate that no gate is asked for: small fixed objects, the first call's class data. */
    public static final long SLACK = 64 << 10;

    private final long limit;
    private long granted;

    public CountingGate(long limit) {
        this.limit = limit;
    }

    public CountingGate() {
        this(Long.MAX_VALUE);
    }

    @Override
    public void reserve(long bytes) {
        if (bytes < 0) {
            throw new IllegalArgumentException("asked for a negative amount: " + bytes);
        }
        if (bytes > limit - granted) {
            throw new Refused();
        }
        granted += bytes;
    }

    @Override
    public boolean tryReserve(long bytes) {
        if (bytes < 0) {
            throw new IllegalArgumentException("asked for a negative amount: " + bytes);
        }
        if (bytes > limit - granted) {
            return false;
        }
        granted += bytes;
        return true;
    }

    public long granted() {
        return granted;
    }

    /** Bytes the current thread allocates while {@code work} runs (the work may throw {@link Refused}). */
    public static long allocatedBy(Runnable work) {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long thread = Thread.currentThread().getId();
        long before = threads.getThreadAllocatedBytes(thread);
        try {
            work.run();
        } catch (Refused expected) {
            // what was allocated until the refusal is the measure
        }
        return threads.getThreadAllocatedBytes(thread) - before;
    }

    /** The gate said no. */
    public static final class Refused extends RuntimeException {
        Refused() {
            super("refused by the test's memory gate", null, false, false);
        }
    }
}

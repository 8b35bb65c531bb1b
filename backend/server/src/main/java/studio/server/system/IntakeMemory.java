package studio.server.system;

import java.time.Duration;
import java.util.Objects;

import jakarta.servlet.ServletRequest;
import studio.engine.memory.MemoryGate;

/**
 * The memory one request holds from the {@link MemoryBudget} while its body is read and compiled
 * into a scene. It starts at nothing and grows with the work, each step reserved before it is
 * taken: the body as it arrives ({@link BodyMemory}: its bytes and what parsing them builds), then
 * what the engine asks for while it reads the meshes and builds their BVHs. A client that sends
 * slowly, or not at all, so holds only what it has sent.
 *
 * <p>When the compiled scene's render reserves its own memory, the compile's share passes to it in
 * the same step ({@link #handOver}): the scene is then counted by its render, the parse is garbage,
 * and only the body's bytes stay here until the request ends.
 *
 * <p>A refusal is an answer: {@link MemoryExceededException} (413) when this request alone needs
 * more than the whole budget, {@link MemoryBusyException} (503 with Retry-After) while other work
 * holds the memory. Before the latter, the first request refused waits up to {@link #WAIT} for
 * memory to come free, while the others are refused at once ({@link MemoryBudget.Reservation#growOrWait}).
 */
public final class IntakeMemory implements MemoryGate, AutoCloseable {

    /** No budget: nothing is counted (the command line, tests that start renders directly). */
    public static final IntakeMemory NONE = new IntakeMemory(null, null);

    /** How long a request refused memory may wait for it: as long as a client is told to wait before retrying. */
    static final Duration WAIT = Duration.ofSeconds(MemoryBusyException.RETRY_AFTER_SECONDS);

    static final int RAW_BYTES_PER_BYTE = 3;

    private static final String ATTRIBUTE = IntakeMemory.class.getName();

    private final MemoryBudget budget;
    private final MemoryBudget.Reservation reservation;
    private long bodyBytes;

    private IntakeMemory(MemoryBudget budget, MemoryBudget.Reservation reservation) {
        this.budget = budget;
        this.reservation = reservation;
    }

    /** A request's memory, holding nothing yet. */
    public static IntakeMemory of(MemoryBudget budget) {
        return new IntakeMemory(budget, Objects.requireNonNull(budget.tryReserve(0)));
    }

    /** The memory of a request that {@link IntakeMemoryFilter} has seen, else {@link #NONE}. */
    public static IntakeMemory of(ServletRequest request) {
        return request.getAttribute(ATTRIBUTE) instanceof IntakeMemory intake ? intake : NONE;
    }

    void attachTo(ServletRequest request) {
        request.setAttribute(ATTRIBUTE, this);
    }

    /** Grants {@code bytes} the work can do without only if they are free now: no waiting, no refusal. */
    @Override
    public boolean tryReserve(long bytes) {
        return reservation == null || reservation.tryGrow(bytes);
    }

    /** Reserves what {@code length} more bytes of the body will take once read and parsed. */
    public void bodyArrived(byte[] buffer, int offset, int length) {
        reserve(BodyMemory.of(buffer, offset, length));
        bodyBytes += length;
    }

    /**
     * Reserves what {@code length} more bytes of a body that is not parsed (an asset's bytes) take:
     * {@value #RAW_BYTES_PER_BYTE} a byte, for the buffer they arrive in (which grows by doubling) and
     * the array they are handed over as.
     */
    public void rawBodyArrived(byte[] buffer, int offset, int length) {
        reserve((long) RAW_BYTES_PER_BYTE * length);
        bodyBytes += length;
    }

    /**
     * @throws MemoryBusyException     if other work holds the memory now
     * @throws MemoryExceededException if this request would hold more than the whole budget
     */
    @Override
    public void reserve(long bytes) {
        if (reservation == null || reservation.tryGrow(bytes)) {
            return;
        }
        if (reservation.bytes() + bytes > budget.capacity()) {
            throw new MemoryExceededException(budget.capacity());
        }
        if (!reservation.growOrWait(bytes, WAIT)) {
            throw new MemoryBusyException();
        }
    }

    /** Bytes held now. */
    public long bytes() {
        return reservation != null ? reservation.bytes() : 0;
    }

    /**
     * Reserves {@code bytes} of {@code memory} for the work that follows the compile, in the same
     * step in which this gives back all but the body's bytes.
     *
     * @return the work's reservation, or null if the budget cannot cover it now
     */
    public MemoryBudget.Reservation handOver(MemoryBudget memory, long bytes) {
        if (reservation == null) {
            return memory.tryReserve(bytes);
        }
        if (memory != budget) {
            throw new IllegalArgumentException("a request's memory passes only to work on the same budget");
        }
        return reservation.tryHandOver(bytes, bodyBytes);
    }

    @Override
    public void close() {
        if (reservation != null) {
            reservation.close();
        }
    }
}

package studio.server.cluster;

import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicBoolean;

import com.hazelcast.ringbuffer.ReadResultSet;

import studio.server.job.JobEvent;
import studio.server.job.JobListener;
import studio.server.job.JobStatus;
import studio.server.job.TileEvent;

/**
 * An event stream of a job that another member runs, read from the job's ring buffer: the status
 * now, the tiles so far, then what follows, and last the end, as a stream of a job of this member
 * would give them. Reads wait asynchronously (no thread waits for the next event) and deliver on
 * the job service's sender threads, one task after another (a batch, or a heartbeat), so the
 * listener hears the events in order, one call at a time, and may write to a slow connection.
 *
 * <p>While the job is quiet, {@link #heartbeat} lets the listener check its connection (an event
 * stream sends a keep-alive comment), as the streams of this member's own jobs do; a listener
 * that went away is {@link #close closed}, and the stream reads no further.
 */
final class RemoteJobStream {

    static final int BATCH = 64;

    private final String id;
    private final SealedMap<String, JobRecord> jobs;
    private final EventLog events;
    private final JobListener listener;
    private final Executor sender;
    /** Status events up to this sequence were past when the listener subscribed: it hears the status now instead. */
    private long pastStatuses;
    private final Queue<Runnable> outbox = new ConcurrentLinkedQueue<>();
    private final AtomicBoolean delivering = new AtomicBoolean();
    private final Runnable onClosed;
    private volatile boolean closed;

    /** @param onClosed run once when the stream ends, is dropped or is closed */
    RemoteJobStream(String id, SealedMap<String, JobRecord> jobs, EventLog events, JobListener listener,
                    Executor sender, Runnable onClosed) {
        this.id = id;
        this.jobs = jobs;
        this.events = events;
        this.listener = listener;
        this.sender = sender;
        this.onClosed = onClosed;
    }

    String jobId() {
        return id;
    }

    void start(JobRecord job) {
        long head = events.headSequence();
        pastStatuses = events.tailSequence();
        post(() -> {
            listener.status(job.status());
            if (job.status().state().isFinal()) {
                end(job.status());
            } else {
                read(head);
            }
        });
    }

    /** Lets the listener check its connection, after whatever it is being told now. */
    void heartbeat() {
        post(() -> {
            if (!closed) {
                listener.heartbeat();
            }
        });
    }

    /**
     * This member is leaving: the listener is dropped (its client reconnects through another member),
     * after whatever it is being told now.
     */
    void drop() {
        post(() -> {
            if (!closed) {
                close();
                listener.dropped();
            }
        });
    }

    /** The listener went away: nothing more is read or delivered (a read already waiting is ignored when it returns). */
    void close() {
        if (!closed) {
            closed = true;
            onClosed.run();
        }
    }

    /** Runs a delivery on the sender pool after the ones before it, never two at once. */
    private void post(Runnable delivery) {
        outbox.add(delivery);
        if (delivering.compareAndSet(false, true)) {
            sender.execute(this::drain);
        }
    }

    private void drain() {
        do {
            for (Runnable next; (next = outbox.poll()) != null; ) {
                next.run();
            }
            delivering.set(false);
            // a task posted after the queue looked empty and before the flag was cleared is run now
        } while (!outbox.isEmpty() && delivering.compareAndSet(false, true));
    }

    private void read(long from) {
        if (closed) {
            return;
        }
        events.readMany(from, 1, BATCH).whenComplete((batch, failure) -> post(() -> deliver(batch, failure)));
    }

    private void end(JobStatus status) {
        close();
        listener.end(status);
    }

    private void deliver(ReadResultSet<byte[]> batch, Throwable failure) {
        if (closed) {
            return;
        }
        if (failure != null) {
            // the job was dropped meanwhile, or this member is leaving: end with what the table says, if anything
            JobRecord job;
            try {
                job = jobs.get(id);
            } catch (RuntimeException e) {
                job = null;
            }
            if (job != null && job.status().state().isFinal()) {
                end(job.status());
            } else {
                close();
                listener.dropped();
            }
            return;
        }
        for (int i = 0; i < batch.size(); i++) {
            JobEvent event = events.open(batch, i); // null: not sealed by a member, skipped
            if (event instanceof TileEvent tile) {
                listener.tile(tile);
            } else if (event instanceof JobStatus status) {
                if (status.state().isFinal()) {
                    end(status);
                    return;
                }
                if (batch.getSequence(i) > pastStatuses) {
                    listener.status(status);
                }
            }
        }
        read(batch.getNextSequenceToReadFrom());
    }
}

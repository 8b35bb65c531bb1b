package studio.server.cluster;

import java.util.concurrent.Executor;

import com.hazelcast.map.IMap;
import com.hazelcast.ringbuffer.ReadResultSet;
import com.hazelcast.ringbuffer.Ringbuffer;

import studio.server.job.JobEvent;
import studio.server.job.JobListener;
import studio.server.job.JobStatus;
import studio.server.job.TileEvent;

/**
 * An event stream of a job that another member runs, read from the job's ring buffer: the status
 * now, the tiles so far, then what follows, and last the end, as a stream of a job of this member
 * would give them. Reads wait asynchronously (no thread waits for the next event) and deliver on
 * the job service's sender threads, one batch after another, so the listener hears the events in
 * order and may write to a slow connection.
 */
final class RemoteJobStream {

    static final int BATCH = 64;

    private final String id;
    private final IMap<String, JobRecord> jobs;
    private final Ringbuffer<JobEvent> events;
    private final JobListener listener;
    private final Executor sender;
    /** Status events up to this sequence were past when the listener subscribed: it hears the status now instead. */
    private long pastStatuses;

    RemoteJobStream(String id, IMap<String, JobRecord> jobs, Ringbuffer<JobEvent> events, JobListener listener,
                    Executor sender) {
        this.id = id;
        this.jobs = jobs;
        this.events = events;
        this.listener = listener;
        this.sender = sender;
    }

    void start(JobRecord job) {
        long head = events.headSequence();
        pastStatuses = events.tailSequence();
        sender.execute(() -> {
            listener.status(job.status());
            if (job.status().state().isFinal()) {
                listener.end(job.status());
            } else {
                read(head);
            }
        });
    }

    private void read(long from) {
        events.readManyAsync(from, 1, BATCH, null).whenCompleteAsync(this::deliver, sender);
    }

    private void deliver(ReadResultSet<JobEvent> batch, Throwable failure) {
        if (failure != null) {
            // the job was dropped meanwhile, or this member is leaving: end with what the table says, if anything
            JobRecord job;
            try {
                job = jobs.get(id);
            } catch (RuntimeException e) {
                job = null;
            }
            if (job != null && job.status().state().isFinal()) {
                listener.end(job.status());
            } else {
                listener.dropped();
            }
            return;
        }
        for (int i = 0; i < batch.size(); i++) {
            JobEvent event = batch.get(i);
            if (event instanceof TileEvent tile) {
                listener.tile(tile);
            } else if (event instanceof JobStatus status) {
                if (status.state().isFinal()) {
                    listener.end(status);
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

package studio.server.job;

import java.util.List;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * One listener's outbox: its place in its job's {@link JobEvents}. The job appends events and only
 * {@link #wake wakes} its subscriptions; a subscription's sender (a thread of the job service's
 * sender pool, one at a time per subscription) takes what is new under the log's lock and hands it
 * to the listener outside it. So no render thread and no holder of a job's lock ever waits for a
 * client's connection, and a listener that stops reading holds up nobody but itself: the job
 * service {@link JobEvents#drop drops} it when a delivery has not returned for
 * {@link JobRegistry#STALL_MILLIS}, and the job goes on.
 *
 * <p>The outbox is bounded by the job's log (the tiles so far, which the job keeps anyway for
 * clients that connect late, within its render memory) and copies none of it.
 */
final class JobSubscription {

    /** What one sender pass delivers: the status at subscription, events from the log, the end. */
    record Delivery(JobStatus first, List<JobEvent> events, JobStatus end) {
    }

    final JobListener listener;
    /** The cluster's listener, not a client's. */
    final boolean internal;
    private final JobEvents job;
    private final Executor sender;
    private final AtomicBoolean scheduled = new AtomicBoolean();
    /** Since when a delivery has been under way (System.nanoTime), 0 when none is. */
    private volatile long deliveringSince;
    private volatile boolean heartbeatDue;
    private final AtomicBoolean droppedHeard = new AtomicBoolean();

    // written under the log's lock
    /** The status the listener hears first, until taken. */
    JobStatus first;
    /** The index in the log of the next event to deliver. */
    int next;
    /** The log's length when the listener subscribed: status changes before it are not news to it. */
    int joinedAt;
    /** True once the end was taken for delivery. */
    boolean endTaken;
    /** True once the subscription has left its job: it ended, its client went away, or it was dropped. */
    volatile boolean detached;
    /** True if it left because it fell behind. */
    volatile boolean dropped;

    JobSubscription(JobListener listener, JobEvents job, Executor sender, boolean internal) {
        this.listener = listener;
        this.internal = internal;
        this.job = job;
        this.sender = sender;
    }

    /** Makes sure a sender will look at the job's log soon; never blocks. */
    void wake() {
        if (scheduled.compareAndSet(false, true)) {
            try {
                sender.execute(this::drain);
            } catch (RejectedExecutionException e) {
                scheduled.set(false); // the service has closed: nothing more is delivered
            }
        }
    }

    /** Asks the sender for a keep-alive if it has nothing else to deliver. */
    void heartbeat() {
        heartbeatDue = true;
        wake();
    }

    /** True while one delivery has been under way for longer than {@code nanos}. */
    boolean stalledFor(long nanos, long now) {
        long since = deliveringSince;
        return since != 0 && now - since > nanos;
    }

    private void drain() {
        for (;;) {
            if (detached) {
                scheduled.set(false);
                if (dropped && droppedHeard.compareAndSet(false, true)) {
                    listener.dropped();
                }
                return;
            }
            Delivery delivery = job.take(this);
            if (delivery != null) {
                deliver(delivery);
            } else if (heartbeatDue) {
                heartbeatDue = false;
                deliver(null);
            } else {
                scheduled.set(false);
                // an event appended between take() and here found the sender busy: look once more
                if (!(job.hasNews(this) || heartbeatDue || detached) || !scheduled.compareAndSet(false, true)) {
                    return;
                }
            }
        }
    }

    private void deliver(Delivery delivery) {
        deliveringSince = Math.max(1, System.nanoTime());
        try {
            if (delivery == null) {
                listener.heartbeat();
                return;
            }
            if (delivery.first() != null) {
                listener.status(delivery.first());
            }
            for (JobEvent event : delivery.events()) {
                if (detached) {
                    return;
                }
                if (event instanceof TileEvent tile) {
                    listener.tile(tile);
                } else if (event instanceof JobStatus status) {
                    listener.status(status);
                }
            }
            if (delivery.end() != null && !detached) {
                listener.end(delivery.end());
                job.detach(this);
            }
        } catch (RuntimeException e) {
            job.detach(this); // a listener that fails hears nothing more
        } finally {
            deliveringSince = 0;
        }
    }
}

package studio.server.job;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Executor;

/**
 * A job's event log (its status changes and the tiles finished so far, for clients that connect
 * late) and the subscriptions that read it. The job appends to it, and marks its end, holding the
 * job's lock; this class has a lock of its own and never calls back into the job, so the order is
 * always job, then log. A subscription's sender takes what is new here and hands it to its listener
 * outside every lock. Once the job has ended and its last subscriber has heard the end, the log is
 * let go: the job is kept for a while only for its status and image.
 */
final class JobEvents {

    /** At most this many events of the log go to a listener in one pass of its sender. */
    static final int DELIVERY_BATCH = 64;

    /** Status changes and finished tiles, in order; cleared when the job is final and nobody reads it. */
    private final List<JobEvent> log = new ArrayList<>();
    private final List<JobSubscription> subscriptions = new ArrayList<>();
    /** The job's final status, once it has one. */
    private JobStatus end;

    /** Appends an event and wakes the subscriptions' senders. */
    synchronized void add(JobEvent event) {
        log.add(event);
        wakeAll();
    }

    /** The job is final: subscriptions hear {@code status} last, after what the log holds for them. */
    synchronized void ended(JobStatus status) {
        end = status;
        if (subscriptions.isEmpty()) {
            log.clear();
        }
        wakeAll();
    }

    /**
     * Registers a listener: its sender delivers {@code now} (the job's status), every tile so far,
     * then what follows, and last the end. An {@code internal} listener (the one that tells the
     * cluster) is no client: it does not count as one watching the job.
     */
    synchronized JobSubscription subscribe(JobListener listener, Executor sender, boolean internal, JobStatus now) {
        JobSubscription subscription = new JobSubscription(listener, this, sender, internal);
        subscription.first = now;
        subscription.joinedAt = log.size();
        subscription.next = end != null ? log.size() : 0;
        subscriptions.add(subscription);
        subscription.wake();
        return subscription;
    }

    /** What the subscription has not heard yet (at most a batch of the log), or null if nothing. */
    synchronized JobSubscription.Delivery take(JobSubscription subscription) {
        if (subscription.detached) {
            return null;
        }
        JobStatus first = subscription.first;
        subscription.first = null;
        int from = subscription.next, to = Math.min(log.size(), from + DELIVERY_BATCH);
        List<JobEvent> events = new ArrayList<>(to - from);
        for (int i = from; i < to; i++) {
            JobEvent event = log.get(i);
            if (event instanceof TileEvent || i >= subscription.joinedAt) {
                events.add(event);
            }
        }
        subscription.next = to;
        JobStatus last = null;
        if (end != null && to == log.size() && !subscription.endTaken) {
            subscription.endTaken = true;
            last = end;
        }
        return first == null && events.isEmpty() && last == null ? null
                : new JobSubscription.Delivery(first, events, last);
    }

    /** True if {@link #take} has something for the subscription. */
    synchronized boolean hasNews(JobSubscription subscription) {
        return !subscription.detached && (subscription.first != null || subscription.next < log.size()
                || end != null && !subscription.endTaken);
    }

    /** The subscription leaves the job (it heard the end, or its client went away); true if it was there. */
    synchronized boolean detach(JobSubscription subscription) {
        subscription.detached = true;
        boolean removed = subscriptions.remove(subscription);
        if (end != null && subscriptions.isEmpty()) {
            log.clear();
        }
        return removed;
    }

    /** Drops a subscription that fell behind; the job goes on. Its sender tells its listener when free. */
    synchronized void drop(JobSubscription subscription) {
        subscription.dropped = true;
        detach(subscription);
        subscription.wake();
    }

    /** Drops every client's subscription (not the cluster's), so that they reconnect elsewhere. */
    synchronized void dropClients() {
        for (JobSubscription subscription : new ArrayList<>(subscriptions)) {
            if (!subscription.internal) {
                drop(subscription);
            }
        }
    }

    /** The subscriptions whose deliveries have not returned for {@code nanos}. */
    synchronized List<JobSubscription> stalled(long nanos, long now) {
        List<JobSubscription> stalled = new ArrayList<>();
        for (JobSubscription subscription : subscriptions) {
            if (subscription.stalledFor(nanos, now)) {
                stalled.add(subscription);
            }
        }
        return stalled;
    }

    /** Removes the listener's subscription, if it has one. */
    synchronized void unsubscribe(JobListener listener) {
        JobSubscription subscription = subscriptionOf(listener);
        if (subscription != null) {
            detach(subscription);
        }
    }

    /** Removes the listener; true if it was the last client of an unfinished job. */
    synchronized boolean unsubscribeLast(JobListener listener) {
        JobSubscription subscription = subscriptionOf(listener);
        boolean removed = subscription != null && detach(subscription);
        return removed && clients() == 0 && end == null;
    }

    private JobSubscription subscriptionOf(JobListener listener) {
        for (JobSubscription subscription : subscriptions) {
            if (subscription.listener == listener) {
                return subscription;
            }
        }
        return null;
    }

    /** Asks every sender for a keep-alive (lets event streams notice clients that went away). */
    synchronized void heartbeat() {
        for (JobSubscription subscription : subscriptions) {
            subscription.heartbeat();
        }
    }

    /** The clients' subscriptions (not the cluster's). */
    synchronized int clients() {
        int count = 0;
        for (JobSubscription subscription : subscriptions) {
            count += subscription.internal ? 0 : 1;
        }
        return count;
    }

    /** Whether any subscription, the cluster's too, has yet to hear the end. */
    synchronized boolean hasSubscriptions() {
        return !subscriptions.isEmpty();
    }

    private void wakeAll() {
        for (JobSubscription subscription : subscriptions) {
            subscription.wake();
        }
    }
}

package studio.server.job;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.Semaphore;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;

/**
 * The job threads and their queue, with a fixed number of places (threads plus queue): a job takes
 * its place before it is accepted ({@link #takePlace}), so that a request that found room never
 * meets a full queue afterwards, and gives it back when it has run or left the queue. A job taken
 * over from another member runs without a place (it was accepted already); the queue itself is
 * unbounded so that it never refuses one.
 */
final class JobExecutor extends ThreadPoolExecutor {

    private final Semaphore places;
    /** The jobs that hold a place. */
    private final Set<Runnable> placed = ConcurrentHashMap.newKeySet();

    JobExecutor(int concurrent, int queue, ThreadFactory threads) {
        super(concurrent, concurrent, 0, TimeUnit.SECONDS, new LinkedBlockingQueue<>(), threads);
        this.places = new Semaphore(concurrent + queue);
    }

    /** True while every place is taken. */
    boolean full() {
        return places.availablePermits() == 0;
    }

    /** Takes a place for a job about to be accepted: false if there is none. */
    boolean takePlace() {
        return places.tryAcquire();
    }

    /** Runs a job in the place {@link #takePlace} took for it (or, with {@code placed} false, without one). */
    void execute(Runnable job, boolean placed) {
        if (placed) {
            this.placed.add(job);
        }
        try {
            execute(job);
        } catch (RuntimeException e) {
            givePlaceOf(job);
            throw e;
        }
    }

    @Override
    public boolean remove(Runnable job) {
        boolean removed = super.remove(job);
        if (removed) {
            givePlaceOf(job);
        }
        return removed;
    }

    @Override
    protected void afterExecute(Runnable job, Throwable failure) {
        givePlaceOf(job);
    }

    private void givePlaceOf(Runnable job) {
        if (placed.remove(job)) {
            places.release();
        }
    }
}

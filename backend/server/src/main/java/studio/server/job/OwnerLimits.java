package studio.server.job;

import java.util.Collection;
import java.util.HashMap;
import java.util.Map;
import java.util.function.IntSupplier;
import java.util.function.Supplier;

/**
 * How many jobs one principal has queued or running on this member, against their limit
 * ({@link JobOwner#maxJobs}), so that one principal cannot fill the queue for everyone. A job being
 * admitted holds a pending place from its count until it is in the registry (then it counts as
 * queued) or refused: simultaneous requests cannot pass the limit, and the lock is held only while
 * counting, never while a job is admitted (which may write to the cluster).
 */
final class OwnerLimits {

    private final Supplier<Collection<RenderJob>> jobs;
    private final IntSupplier retryAfterSeconds;
    /** Jobs being admitted, by principal. */
    private final Map<String, Integer> pending = new HashMap<>();

    OwnerLimits(Supplier<Collection<RenderJob>> jobs, IntSupplier retryAfterSeconds) {
        this.jobs = jobs;
        this.retryAfterSeconds = retryAfterSeconds;
    }

    /** Refuses at once while {@code owner} has as many jobs as they may: a cheap check before a scene is read. */
    synchronized void check(JobOwner owner) {
        if (owner.maxJobs() != Integer.MAX_VALUE) {
            refuseIfFull(owner);
        }
    }

    /**
     * Takes a pending place for one more job of {@code owner}; run the answer once the job is admitted
     * or refused.
     *
     * @throws JobQueueFullException (429) while the owner has as many jobs as they may
     */
    synchronized Runnable take(JobOwner owner) {
        if (owner.maxJobs() == Integer.MAX_VALUE) {
            return () -> {
            };
        }
        refuseIfFull(owner);
        pending.merge(owner.principal(), 1, Integer::sum);
        return () -> release(owner.principal());
    }

    private synchronized void release(String principal) {
        pending.computeIfPresent(principal, (p, count) -> count > 1 ? count - 1 : null);
    }

    private void refuseIfFull(JobOwner owner) {
        int active = pending.getOrDefault(owner.principal(), 0);
        for (RenderJob job : jobs.get()) {
            if (job.principal().equals(owner.principal()) && !job.state().isFinal()) {
                active++;
            }
        }
        if (active >= owner.maxJobs()) {
            throw new JobQueueFullException(retryAfterSeconds.getAsInt(), "you have " + active + " render jobs "
                    + "queued or running, as many as one principal may (studio.security.max-jobs-per-principal="
                    + owner.maxJobs() + ")");
        }
    }
}

package studio.server.cluster;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A stopping member's jobs, handed to the others at once (SIGTERM in a rolling restart): this member
 * stops taking tiles and hands back those it holds, writes nothing more of the jobs (its coordinators
 * stop and leave the jobs' tiles in the cluster), then releases each job in the job table (owner
 * empty). The other members take released jobs over by the same path as a dead member's
 * ({@link TakeOver}), as soon as they see the release; this member waits, boundedly, until each has
 * a new owner and then leaves.
 */
final class HandOver {

    private static final Logger log = LoggerFactory.getLogger(HandOver.class);
    /** The owner of a job released by a stopping member: no member's id. */
    static final String RELEASED = "";
    /** While waiting for the new owners, the job table is read this often. */
    static final long CHECK_MILLIS = 50;

    private final SealedMap<String, JobRecord> jobs;
    private final String memberId;
    private final Set<String> handedOver = ConcurrentHashMap.newKeySet();
    private volatile boolean leaving;

    HandOver(SealedMap<String, JobRecord> jobs, String memberId) {
        this.jobs = jobs;
        this.memberId = memberId;
    }

    /** True once this member hands its jobs over: it takes none over itself. */
    boolean leaving() {
        return leaving;
    }

    /** True for a job this member handed over: it writes nothing more of it, and leaves its tiles be. */
    boolean handedOver(String id) {
        return handedOver.contains(id);
    }

    /**
     * Releases each job in the job table, and marks those released as handed over. Called once the
     * member's workers have stopped. A job that ends meanwhile is not released: it ends here as usual
     * (its end is written by whoever wins the job's entry; once released, a late end of this member's
     * is refused there, and the job's new owner ends it).
     */
    void release(Set<String> ids) {
        leaving = true;
        for (String id : ids) {
            try {
                if (jobs.update(id, new TakeOver(memberId, RELEASED))) {
                    handedOver.add(id);
                } else {
                    log.info("job {} was not released: it ended, or another member owns it", id);
                }
            } catch (RuntimeException e) {
                log.warn("could not release job {}: {}; the others take it over once this member has left", id,
                        e.toString());
            }
        }
    }

    /**
     * Waits until every job handed over has a new owner (or ended, or is gone), at most until the
     * deadline ({@link System#nanoTime()}).
     *
     * @return true if all have
     */
    boolean await(long deadlineNanos) throws InterruptedException {
        Set<String> waiting = ConcurrentHashMap.newKeySet();
        waiting.addAll(handedOver);
        while (true) {
            waiting.removeIf(id -> {
                try {
                    JobRecord job = jobs.get(id);
                    return job == null || job.status().state().isFinal() || !RELEASED.equals(job.owner());
                } catch (RuntimeException e) {
                    return false;
                }
            });
            if (waiting.isEmpty()) {
                return true;
            }
            if (System.nanoTime() - deadlineNanos > 0) {
                log.warn("{} jobs handed over have no new owner yet; the others take them over once this member "
                        + "has left", waiting.size());
                return false;
            }
            Thread.sleep(CHECK_MILLIS);
        }
    }
}

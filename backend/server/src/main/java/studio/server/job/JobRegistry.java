package studio.server.job;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;

/**
 * This member's jobs by id, finished ones included for a while: who may see each one, and the
 * janitor's rounds that drop expired finished jobs, cancel abandoned ones and drop listeners that
 * stopped reading.
 */
final class JobRegistry {

    /** A listener whose delivery has not returned for this long is dropped (see {@link JobSubscription}). */
    static final long STALL_MILLIS = 5_000;

    private final Map<String, RenderJob> jobs = new ConcurrentHashMap<>();
    private final JobSettings settings;
    private final JobCluster cluster;
    private final JobExecutor executor;

    JobRegistry(JobSettings settings, JobCluster cluster, JobExecutor executor) {
        this.settings = settings;
        this.cluster = cluster;
        this.executor = executor;
    }

    void put(RenderJob job) {
        jobs.put(job.id(), job);
    }

    boolean contains(String id) {
        return jobs.containsKey(id);
    }

    /** This member's job of that id, or null. */
    RenderJob get(String id) {
        return jobs.get(id);
    }

    /** This member's job of that id; {@link JobNotFoundException} if it has none. */
    RenderJob job(String id) {
        RenderJob job = jobs.get(id);
        if (job == null) {
            throw new JobNotFoundException(id);
        }
        return job;
    }

    /**
     * This member's job of that id, if {@code principal}'s; null if this member has none.
     *
     * @throws JobNotFoundException if it is someone else's: a job's id tells nobody else anything
     */
    RenderJob local(String id, String principal) {
        RenderJob job = jobs.get(id);
        if (job != null && !job.principal().equals(principal)) {
            throw new JobNotFoundException(id);
        }
        return job;
    }

    Collection<RenderJob> all() {
        return jobs.values();
    }

    /** Forgets a job here and gives back its memory (not in the cluster). */
    void forget(RenderJob job) {
        jobs.remove(job.id());
        job.release();
    }

    int size() {
        return jobs.size();
    }

    /** The clients listening to this member's jobs, over all of them. */
    int listeners() {
        int listeners = 0;
        for (RenderJob job : jobs.values()) {
            listeners += job.subscriptionCount();
        }
        return listeners;
    }

    /**
     * Drops every listener whose delivery has not returned for {@value #STALL_MILLIS} ms (its client
     * does not read its event stream): it hears nothing more, and its job goes on.
     */
    void dropStalledListeners() {
        long now = System.nanoTime();
        for (RenderJob job : jobs.values()) {
            for (JobSubscription stalled : job.stalled(TimeUnit.MILLISECONDS.toNanos(STALL_MILLIS), now)) {
                job.drop(stalled);
            }
        }
    }

    /** Drops expired finished jobs (beyond the time or the count) and cancels abandoned ones. */
    void sweep() {
        long now = System.nanoTime();
        List<RenderJob> finished = new ArrayList<>();
        for (RenderJob job : jobs.values()) {
            JobState state = job.state();
            if (state.isFinal()) {
                if (now - job.finishedNanos() > settings.keepFinished().toNanos()) {
                    drop(job);
                } else {
                    finished.add(job);
                }
            } else {
                job.heartbeat(); // lets event streams notice clients that went away
            }
            if (!state.isFinal() && !job.hasListeners()
                    && now - job.lastSeenNanos() > settings.abandonAfter().toNanos()
                    && System.currentTimeMillis() - cluster.lastSeenMillis(job.id()) > settings.abandonAfter().toMillis()) {
                job.cancel();
                executor.remove(job);
            }
        }
        if (finished.size() > settings.maxFinished()) {
            finished.sort(Comparator.comparingLong(RenderJob::finishedNanos));
            for (RenderJob job : finished.subList(0, finished.size() - settings.maxFinished())) {
                drop(job);
            }
        }
    }

    private void drop(RenderJob job) {
        forget(job);
        cluster.dropped(job.id());
    }
}

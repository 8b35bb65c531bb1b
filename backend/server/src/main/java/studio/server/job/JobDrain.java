package studio.server.job;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

import studio.server.system.Drainable;

/**
 * How a member's jobs end when it stops: it takes no more, cancels what is queued (or, in a
 * cluster, hands every unfinished job to the other members), lets running jobs finish within the
 * grace, and waits for their listeners to hear the end.
 */
final class JobDrain implements Drainable {

    private final JobRegistry jobs;
    private final JobExecutor executor;
    private final JobCluster cluster;
    /** The jobs handed to other members on shutdown (see {@link JobCluster#handOver}). */
    private final List<RenderJob> handedOver = new CopyOnWriteArrayList<>();

    JobDrain(JobRegistry jobs, JobExecutor executor, JobCluster cluster) {
        this.jobs = jobs;
        this.executor = executor;
        this.cluster = cluster;
    }

    /**
     * Stops taking jobs (new ones get 429) and cancels the queued ones at once; their listeners hear the end.
     * In a cluster, the unfinished jobs, queued and running, are handed to the other members instead.
     */
    @Override
    public void stopAccepting() {
        executor.shutdown();
        executor.getQueue().clear();
        List<RenderJob> unfinished = jobs.all().stream().filter(job -> !job.state().isFinal()).toList();
        if (cluster.canHandOver()) {
            String reason = "handed over to another member";
            // clients first (they hear no end from here), then the cluster stops the renders, then they end here
            unfinished.forEach(job -> job.handingOver(reason));
            cluster.handOver(unfinished.stream().map(RenderJob::id).collect(Collectors.toSet()));
            unfinished.forEach(job -> job.cancel(reason));
            handedOver.addAll(unfinished);
            return;
        }
        for (RenderJob job : jobs.all()) {
            if (job.state() == JobState.QUEUED) {
                job.cancel("cancelled: the server is shutting down");
            }
        }
    }

    /**
     * Waits until the running jobs have ended and their listeners have heard the end (or left), at
     * most until the deadline.
     *
     * @return true if every job ended
     */
    @Override
    public boolean awaitEnd(long deadlineNanos) throws InterruptedException {
        boolean ended = executor.awaitTermination(Math.max(0, deadlineNanos - System.nanoTime()), TimeUnit.NANOSECONDS);
        awaitListeners(deadlineNanos);
        if (!handedOver.isEmpty()) {
            // served by their new owners from now on; forgotten here, not in the cluster
            ended &= cluster.awaitHandedOver(deadlineNanos);
            for (RenderJob job : handedOver) {
                jobs.forget(job);
            }
            handedOver.clear();
        }
        return ended;
    }

    /** Cancels the jobs still running (they stop within a tile) and waits for that as {@link #awaitEnd}. */
    @Override
    public void cancelRunning(long deadlineNanos) throws InterruptedException {
        for (RenderJob job : jobs.all()) {
            if (!job.state().isFinal()) {
                job.cancel("cancelled: the server shut down before the render finished");
            }
        }
        awaitEnd(deadlineNanos);
    }

    /** Until the deadline, waits for every listener of a finished job to hear its end (a stalled one is dropped). */
    private void awaitListeners(long deadlineNanos) throws InterruptedException {
        while (System.nanoTime() - deadlineNanos < 0) {
            boolean heard = true;
            for (RenderJob job : jobs.all()) {
                heard &= !job.state().isFinal() || !job.hasSubscriptions();
            }
            if (heard) {
                return;
            }
            Thread.sleep(10);
        }
    }
}

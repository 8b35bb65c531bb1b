package studio.server.job;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.UUID;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import studio.server.scene.CompiledScene;

/**
 * Runs render jobs on a bounded executor (a few at once, a short queue, then 429), keeps them
 * for a while after they finish, and cancels work nobody is waiting for any more.
 */
public final class JobService implements AutoCloseable {

    private final JobSettings settings;
    private final ThreadPoolExecutor executor;
    private final ScheduledExecutorService janitor;
    private final Map<String, RenderJob> jobs = new ConcurrentHashMap<>();

    public JobService(JobSettings settings) {
        this.settings = settings;
        AtomicInteger threads = new AtomicInteger();
        this.executor = new ThreadPoolExecutor(settings.concurrent(), settings.concurrent(), 0, TimeUnit.SECONDS,
                new ArrayBlockingQueue<>(settings.queue()),
                r -> {
                    Thread t = new Thread(r, "render-job-" + threads.incrementAndGet());
                    t.setDaemon(true);
                    return t;
                });
        this.janitor = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "render-job-janitor");
            t.setDaemon(true);
            return t;
        });
        janitor.scheduleWithFixedDelay(this::sweep, 5, 5, TimeUnit.SECONDS);
    }

    /**
     * Queues a validated scene.
     *
     * @throws JobQueueFullException when every slot and queue place is taken
     */
    public JobStatus submit(CompiledScene scene) {
        CompiledScene withThreads = new CompiledScene(scene.scene(),
                scene.settings().withThreads(settings.renderThreads()), scene.format(), scene.quality(),
                scene.fileStem());
        RenderJob job = new RenderJob(UUID.randomUUID().toString().replace("-", ""), withThreads);
        jobs.put(job.id(), job);
        try {
            executor.execute(job);
        } catch (RejectedExecutionException e) {
            jobs.remove(job.id());
            throw new JobQueueFullException(retryAfterSeconds());
        }
        return job.status();
    }

    public JobStatus status(String id) {
        RenderJob job = job(id);
        job.touch();
        return job.status();
    }

    public JobStatus cancel(String id) {
        RenderJob job = job(id);
        JobStatus status = job.cancel();
        if (status.state() == JobState.CANCELLED) {
            executor.remove(job);
        }
        return status;
    }

    /** The finished image with its job's status. */
    public JobImage image(String id) {
        RenderJob job = job(id);
        job.touch();
        byte[] image = job.image();
        JobStatus status = job.status();
        if (image == null) {
            throw new JobNotDoneException(id, status.state());
        }
        return new JobImage(status, image);
    }

    /** A finished job's image and status. */
    public record JobImage(JobStatus status, byte[] bytes) {
    }

    void subscribe(String id, JobListener listener) {
        job(id).subscribe(listener);
    }

    void unsubscribe(String id, JobListener listener) {
        RenderJob job = jobs.get(id);
        if (job != null) {
            job.unsubscribe(listener);
        }
    }

    private RenderJob job(String id) {
        RenderJob job = jobs.get(id);
        if (job == null) {
            throw new JobNotFoundException(id);
        }
        return job;
    }

    /** A rough wait before a retry: one typical render per queued job ahead, at least one second. */
    private int retryAfterSeconds() {
        return Math.max(1, executor.getQueue().size() * 2 / Math.max(1, settings.concurrent()));
    }

    /** Drops expired finished jobs (beyond the time or the count) and cancels abandoned ones. */
    void sweep() {
        long now = System.nanoTime();
        List<RenderJob> finished = new ArrayList<>();
        for (RenderJob job : jobs.values()) {
            JobState state = job.state();
            if (state.isFinal()) {
                if (now - job.finishedNanos() > settings.keepFinished().toNanos()) {
                    jobs.remove(job.id());
                } else {
                    finished.add(job);
                }
            } else {
                job.heartbeat(); // lets event streams notice clients that went away
            }
            if (!state.isFinal() && !job.hasListeners()
                    && now - job.lastSeenNanos() > settings.abandonAfter().toNanos()) {
                job.cancel();
                executor.remove(job);
            }
        }
        if (finished.size() > settings.maxFinished()) {
            finished.sort(Comparator.comparingLong(RenderJob::finishedNanos));
            for (RenderJob job : finished.subList(0, finished.size() - settings.maxFinished())) {
                jobs.remove(job.id());
            }
        }
    }

    /** Jobs known right now, finished ones included (for tests and metrics). */
    int size() {
        return jobs.size();
    }

    /** Cancels everything and stops the workers, waiting up to {@code graceMillis} for running renders. */
    public void shutdown(long graceMillis) {
        janitor.shutdownNow();
        executor.shutdown();
        for (RenderJob job : jobs.values()) {
            if (!job.state().isFinal()) {
                job.cancel();
            }
        }
        try {
            executor.awaitTermination(graceMillis, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        executor.shutdownNow();
    }

    @Override
    public void close() {
        shutdown(5_000);
    }
}

package studio.server.job;

import java.time.Duration;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import studio.server.render.RenderBudget;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.format.InvalidSceneException;
import studio.server.system.Drainable;
import studio.server.system.IntakeMemory;
import studio.server.system.MemoryBudget;

/**
 * Runs render jobs on a bounded executor (a few at once, a short queue, then 429), each within the
 * {@link RenderBudget} (its memory is reserved when it is accepted, so a queued job cannot fail for
 * lack of it later), keeps them for a while after they finish, and cancels work nobody is waiting
 * for any more: a job whose last event stream broke, or that nobody has asked about for a while.
 */
public final class JobService implements Drainable, AutoCloseable {

    /** Null in a service that is handed compiled scenes only. */
    private final SceneCompiler compiler;
    private final JobSettings settings;
    private final RenderBudget budget;
    private final Duration shutdownGrace;
    private final JobExecutor executor;
    private final ScheduledExecutorService janitor;
    /** Delivers events to listeners (see {@link JobSubscription}): a thread per subscription while it has news. */
    private final ExecutorService senders;
    private final JobRegistry jobs;
    private final JobDrain drain;
    private final JobCluster cluster;
    private final OwnerLimits ownerLimits;

    /** Listeners (event streams) at once, over all jobs; each holds a sender thread while it has news. */
    static final int MAX_LISTENERS = 256;

    /**
     * A service that is handed compiled scenes only ({@link #submit}; {@link #start} refuses): a
     * cluster member's tests compile their scenes themselves.
     */
    public JobService(JobSettings settings, RenderBudget budget, Duration shutdownGrace, JobCluster cluster) {
        this(null, settings, budget, shutdownGrace, cluster);
    }

    /** A service outside Spring (tests), in a cluster of one, without a memory or time limit. */
    public JobService(SceneCompiler compiler, JobSettings settings) {
        this(compiler, settings, RenderBudget.unlimited(), Duration.ofSeconds(5), JobCluster.SINGLE);
    }

    /**
     * @param compiler      reads the scenes {@link #start} is given
     * @param shutdownGrace on shutdown, how long running jobs may go on before they are cancelled
     * @param cluster       where jobs' tiles are rendered and who else sees them ({@link JobCluster#SINGLE}:
     *                      this member only)
     */
    public JobService(SceneCompiler compiler, JobSettings settings, RenderBudget budget, Duration shutdownGrace,
                      JobCluster cluster) {
        this.compiler = compiler;
        this.settings = settings;
        this.cluster = cluster;
        this.budget = budget;
        this.shutdownGrace = shutdownGrace;
        this.executor = new JobExecutor(settings.concurrent(), settings.queue(), daemons("render-job-"));
        this.jobs = new JobRegistry(settings, cluster, executor);
        this.drain = new JobDrain(jobs, executor, cluster);
        this.ownerLimits = new OwnerLimits(jobs::all, this::retryAfterSeconds);
        this.janitor = Executors.newSingleThreadScheduledExecutor(daemons("render-job-janitor-"));
        janitor.scheduleWithFixedDelay(jobs::sweep, 5, 5, TimeUnit.SECONDS);
        janitor.scheduleWithFixedDelay(jobs::dropStalledListeners, 1, 1, TimeUnit.SECONDS);
        this.senders = Executors.newCachedThreadPool(daemons("job-events-"));
        cluster.start(this::resume);
    }

    private static ThreadFactory daemons(String prefix) {
        AtomicInteger count = new AtomicInteger();
        return r -> {
            Thread t = new Thread(r, prefix + count.incrementAndGet());
            t.setDaemon(true);
            return t;
        };
    }

    /**
     * Refuses at once ({@link JobQueueFullException}, a 429) while the queue is full or the server
     * is shutting down, so that a refused request costs no scene reading: compiling a mesh scene
     * takes far longer than answering. {@link #submit} checks again. The price: while the queue is
     * full, an invalid scene, too, is answered 429 first, and its 400 comes on the retry.
     */
    public void checkRoom() {
        if (executor.isShutdown()) {
            throw new JobQueueFullException(retryAfterSeconds(), "the server is shutting down");
        }
        if (executor.full()) {
            throw new JobQueueFullException(retryAfterSeconds());
        }
    }

    /**
     * Reads a scene and queues it, as {@code POST /api/jobs} does: refuses at once while there is no
     * room ({@link #checkRoom}) or {@code owner} is at their limit, then compiles the scene with this
     * service's threads per render, its building drawn on the request's {@code intake}, which hands
     * its memory over to the job's.
     *
     * @param sceneJson the scene as sent; in a cluster it travels to the members that render the job's tiles
     * @throws JobQueueFullException when every slot and queue place, or the memory the render needs, is taken
     * @throws InvalidSceneException when the scene is invalid or its render could never fit the memory budget
     */
    public JobStatus start(byte[] sceneJson, IntakeMemory intake, JobOwner owner) {
        if (compiler == null) {
            throw new IllegalStateException("this job service is handed compiled scenes only; submit them");
        }
        checkRoom();
        ownerLimits.check(owner);
        CompiledScene scene = compiler.compile(CompileRequest.of(sceneJson).onThreads(settings.renderThreads()).within(intake));
        return submit(new JobRequest(scene, sceneJson, intake, owner));
    }

    /**
     * Queues a validated scene. A limited owner's count and new job are taken together, so that
     * simultaneous requests cannot pass the limit.
     *
     * @throws JobQueueFullException when every slot and queue place, or the memory the render needs, is taken
     * @throws InvalidSceneException when the render could never fit the memory budget
     */
    public JobStatus submit(JobRequest request) {
        Runnable admitted = ownerLimits.take(request.owner());
        try {
            return admit(request.scene(), request.sceneJson(), request.intake(), request.owner());
        } finally {
            admitted.run();
        }
    }

    private JobStatus admit(CompiledScene scene, byte[] sceneJson, IntakeMemory intake, JobOwner owner) {
        checkRoom();
        CompiledScene withThreads = new CompiledScene(scene.scene(),
                scene.settings().withThreads(settings.renderThreads()), scene.format(), scene.quality(),
                scene.fileStem());
        MemoryBudget.Reservation memory = budget.reserve(withThreads, intake);
        if (memory == null) {
            throw new JobQueueFullException(retryAfterSeconds(), "the server's render memory is taken by other jobs");
        }
        return start(UUID.randomUUID().toString().replace("-", ""), owner.principal(), withThreads, sceneJson, memory,
                false);
    }

    private JobStatus start(String id, String principal, CompiledScene scene, byte[] sceneJson,
                            MemoryBudget.Reservation memory, boolean resumed) {
        // a new job takes its place before anyone hears of it; one taken over needs none
        if (!resumed && !executor.takePlace()) {
            memory.close();
            throw new JobQueueFullException(retryAfterSeconds());
        }
        RenderJob job = new RenderJob(id, principal, scene, budget, memory,
                (compiled, listener, cancelled) -> cluster.render(id, compiled, budget, listener, cancelled),
                () -> cluster.workers(id), (end, image) -> cluster.ending(id, end, image));
        jobs.put(job);
        JobListener publisher = cluster.accepted(id, principal, sceneJson, job::status, job::image, resumed);
        if (publisher != null) {
            job.subscribe(publisher, senders, true);
        }
        JobLog.accepted(id, scene, resumed, executor.getQueue().size());
        try {
            executor.execute(job, !resumed);
        } catch (RejectedExecutionException e) {
            job.fail("the server is shutting down");
            jobs.forget(job);
            throw new JobQueueFullException(retryAfterSeconds());
        }
        return job.status();
    }

    /**
     * Takes over the job of a member that died (see {@link JobCluster.Takeover}): it runs here from
     * now on, even beyond the queue's length (it was accepted already), its memory taken even if the
     * budget is full (refusing it would lose the job).
     */
    void resume(String id, String principal, CompiledScene compiled, byte[] sceneJson) {
        if (jobs.contains(id)) {
            return;
        }
        CompiledScene withThreads = new CompiledScene(compiled.scene(),
                compiled.settings().withThreads(settings.renderThreads()), compiled.format(), compiled.quality(),
                compiled.fileStem());
        MemoryBudget.Reservation memory = budget.memory().forceReserve(
                studio.server.render.RenderMemory.estimate(withThreads));
        start(id, principal, withThreads, sceneJson, memory, true);
    }

    /** A job's status, with sign-in off. */
    public JobStatus status(String id) {
        return status(id, "");
    }

    /**
     * A job's status, if it is {@code principal}'s: anyone else's job answers as if it did not exist
     * ({@link JobNotFoundException}), so that a job's id tells nobody else anything.
     */
    public JobStatus status(String id, String principal) {
        RenderJob job = jobs.local(id, principal);
        if (job == null) {
            return known(cluster.status(id, principal), id);
        }
        job.touch();
        return job.status();
    }

    /** Cancels a job, with sign-in off. */
    public JobStatus cancel(String id) {
        return cancel(id, "");
    }

    /** Cancels a job if it is {@code principal}'s (see {@link #status(String, String)}). */
    public JobStatus cancel(String id, String principal) {
        RenderJob job = jobs.local(id, principal);
        if (job == null) {
            return known(cluster.cancel(id, principal), id);
        }
        return cancel(job);
    }

    private JobStatus cancel(RenderJob job) {
        JobStatus status = job.cancel();
        if (status.state() == JobState.CANCELLED) {
            executor.remove(job);
        }
        return status;
    }

    /** The finished image with its job's status, with sign-in off. */
    public JobImage image(String id) {
        return image(id, "");
    }

    /** The finished image with its job's status, if {@code principal}'s (see {@link #status(String, String)}). */
    public JobImage image(String id, String principal) {
        RenderJob job = jobs.local(id, principal);
        byte[] image;
        JobStatus status;
        if (job != null) {
            job.touch();
            image = job.image();
            status = job.status();
        } else {
            status = known(cluster.status(id, principal), id);
            image = status.state() == JobState.DONE ? cluster.image(id, principal) : null;
        }
        if (image == null) {
            throw new JobNotDoneException(id, status.state());
        }
        return new JobImage(status, image);
    }

    /**
     * Subscribes a listener to a job's events.
     *
     * @throws JobQueueFullException when {@value #MAX_LISTENERS} listeners are subscribed already
     */
    void subscribe(String id, JobListener listener) {
        subscribe(id, "", listener);
    }

    /** As {@link #subscribe(String, JobListener)}, to a job of {@code principal}'s (see {@link #status(String, String)}). */
    void subscribe(String id, String principal, JobListener listener) {
        RenderJob job = jobs.local(id, principal);
        if (job == null) {
            if (!cluster.subscribe(id, principal, listener, senders)) {
                throw new JobNotFoundException(id);
            }
            return;
        }
        if (jobs.listeners() >= MAX_LISTENERS) {
            throw new JobQueueFullException(retryAfterSeconds(), "the server has as many event streams open as it "
                    + "serves (" + MAX_LISTENERS + "); poll the job's status instead, or try again shortly");
        }
        job.subscribe(listener, senders);
    }

    void unsubscribe(String id, JobListener listener) {
        RenderJob job = jobs.get(id);
        if (job != null) {
            job.unsubscribe(listener);
        } else {
            cluster.unsubscribe(id, listener);
        }
    }

    /**
     * A listener's connection broke (its client went away): it is dropped, and if it was the job's
     * last listener, the job is cancelled (it stops within a few milliseconds), as nobody is left to
     * see the result. A client that wants a job to go on without watching it polls its status instead.
     */
    void disconnected(String id, JobListener listener) {
        RenderJob job = jobs.get(id);
        if (job == null) {
            cluster.unsubscribe(id, listener); // another member's job: its stream stops
        } else if (job.unsubscribeLast(listener)) {
            cancel(job);
        }
    }

    /**
     * Runs what an event stream's container callback asks for (the stream completed, failed or
     * timed out) on the janitor's thread instead of the container's. The container calls back
     * holding the request's state lock, which a render thread sending a tile waits for while it holds
     * its job's lock; taking the job's lock in the callback itself deadlocked the two (a CI run:
     * a disconnected job's render thread stopped, and the job was never cancelled).
     */
    void offContainerThread(Runnable work) {
        try {
            janitor.execute(work);
        } catch (RejectedExecutionException e) {
            // shutting down: every job is being cancelled anyway
        }
    }

    private static JobStatus known(JobStatus status, String id) {
        if (status == null) {
            throw new JobNotFoundException(id);
        }
        return status;
    }

    RenderJob job(String id) {
        return jobs.job(id);
    }

    /** A rough wait before a retry: one typical render per queued job ahead, at least one second. */
    private int retryAfterSeconds() {
        return Math.max(1, executor.getQueue().size() * 2 / Math.max(1, settings.concurrent()));
    }

    /** Drops expired finished jobs (beyond the time or the count) and cancels abandoned ones. */
    void sweep() {
        jobs.sweep();
    }

    /** Jobs known right now, finished ones included (for tests and metrics). */
    int size() {
        return jobs.size();
    }

    /** Jobs of this member waiting to run. */
    int queued() {
        return executor.getQueue().size();
    }

    /** Jobs of this member running now. */
    int running() {
        return executor.getActiveCount();
    }

    /** See {@link JobDrain#stopAccepting}. */
    @Override
    public void stopAccepting() {
        drain.stopAccepting();
    }

    @Override
    public boolean awaitEnd(long deadlineNanos) throws InterruptedException {
        return drain.awaitEnd(deadlineNanos);
    }

    @Override
    public void cancelRunning(long deadlineNanos) throws InterruptedException {
        drain.cancelRunning(deadlineNanos);
    }

    /**
     * Stops taking jobs, cancels the queued ones, lets the running ones finish for up to
     * {@code graceMillis}, then cancels them too (they stop within milliseconds) and waits for that, at most
     * {@link Drainable#CANCEL_WAIT_MILLIS}. Every job ends DONE or CANCELLED; nothing is left half
     * done, and every listener that reads hears the end.
     */
    public void shutdown(long graceMillis) {
        Drainable.drain(List.of(this), graceMillis);
        executor.shutdownNow();
        janitor.shutdownNow();
        senders.shutdownNow();
    }

    @Override
    public void close() {
        shutdown(shutdownGrace.toMillis());
    }
}

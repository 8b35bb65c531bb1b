package studio.server.job;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.UUID;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import studio.server.render.RenderBudget;
import studio.server.scene.compiling.CompiledScene;
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
    private final Map<String, RenderJob> jobs = new ConcurrentHashMap<>();
    /** The jobs handed to other members on shutdown (see {@link JobCluster#handOver}). */
    private final List<RenderJob> handedOver = new java.util.concurrent.CopyOnWriteArrayList<>();
    private final JobCluster cluster;
    private final OwnerLimits ownerLimits = new OwnerLimits(jobs::values, this::retryAfterSeconds);

    /** Listeners (event streams) at once, over all jobs; each holds a sender thread while it has news. */
    static final int MAX_LISTENERS = 256;
    /** A listener whose delivery has not returned for this long is dropped (see {@link JobSubscription}). */
    static final long STALL_MILLIS = 5_000;

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
        AtomicInteger threads = new AtomicInteger();
        this.executor = new JobExecutor(settings.concurrent(), settings.queue(),
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
        janitor.scheduleWithFixedDelay(this::dropStalledListeners, 1, 1, TimeUnit.SECONDS);
        AtomicInteger senderThreads = new AtomicInteger();
        this.senders = Executors.newCachedThreadPool(r -> {
            Thread t = new Thread(r, "job-events-" + senderThreads.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
        cluster.start(this::resume);
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
     * room ({@link #checkRoom}), then compiles the scene with this service's threads per render, its
     * building drawn on the request's {@code intake}, which hands its memory over to the job's.
     *
     * @param sceneJson the scene as sent; in a cluster it travels to the members that render the job's tiles
     * @throws JobQueueFullException when every slot and queue place, or the memory the render needs, is taken
     * @throws InvalidSceneException when the scene is invalid or its render could never fit the memory budget
     */
    public JobStatus start(byte[] sceneJson, IntakeMemory intake) {
        return start(sceneJson, intake, JobOwner.ANYONE);
    }

    /** As {@link #start(byte[], IntakeMemory)}, for {@code owner}: only they see the job, within their limit. */
    public JobStatus start(byte[] sceneJson, IntakeMemory intake, JobOwner owner) {
        if (compiler == null) {
            throw new IllegalStateException("this job service is handed compiled scenes only; submit them");
        }
        checkRoom();
        ownerLimits.check(owner);
        return submit(compiler.compile(sceneJson, Map.of(), settings.renderThreads(), intake), sceneJson, intake,
                owner);
    }

    /**
     * Queues a validated scene.
     *
     * @throws JobQueueFullException when every slot and queue place, or the memory the render needs, is taken
     * @throws InvalidSceneException when the render could never fit the memory budget
     */
    public JobStatus submit(CompiledScene scene) {
        return submit(scene, IntakeMemory.NONE);
    }

    /** As {@link #submit(CompiledScene)}; the request's {@code intake} hands its memory over to the job's. */
    public JobStatus submit(CompiledScene scene, IntakeMemory intake) {
        return submit(scene, null, intake);
    }

    /**
     * As {@link #submit(CompiledScene, IntakeMemory)}, with the JSON the scene was compiled from: in a
     * cluster it travels to the members that render the job's tiles.
     */
    public JobStatus submit(CompiledScene scene, byte[] sceneJson, IntakeMemory intake) {
        return submit(scene, sceneJson, intake, JobOwner.ANYONE);
    }

    /**
     * As {@link #submit(CompiledScene, byte[], IntakeMemory)}, for {@code owner}. A limited owner's count
     * and new job are taken together, so that simultaneous requests cannot pass the limit.
     */
    public JobStatus submit(CompiledScene scene, byte[] sceneJson, IntakeMemory intake, JobOwner owner) {
        Runnable admitted = ownerLimits.take(owner);
        try {
            return admit(scene, sceneJson, intake, owner);
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
        jobs.put(job.id(), job);
        JobListener publisher = cluster.accepted(id, principal, sceneJson, job::status, job::image, resumed);
        if (publisher != null) {
            job.subscribe(publisher, senders, true);
        }
        JobLog.accepted(id, scene, resumed, executor.getQueue().size());
        try {
            executor.execute(job, !resumed);
        } catch (RejectedExecutionException e) {
            job.fail("the server is shutting down");
            jobs.remove(job.id());
            job.release();
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
        if (jobs.containsKey(id)) {
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
        RenderJob job = local(id, principal);
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
        RenderJob job = local(id, principal);
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

    /**
     * This member's job of that id, if {@code principal}'s; null if this member has none.
     *
     * @throws JobNotFoundException if it is someone else's
     */
    private RenderJob local(String id, String principal) {
        RenderJob job = jobs.get(id);
        if (job != null && !job.principal().equals(principal)) {
            throw new JobNotFoundException(id);
        }
        return job;
    }

    /** The finished image with its job's status, with sign-in off. */
    public JobImage image(String id) {
        return image(id, "");
    }

    /** The finished image with its job's status, if {@code principal}'s (see {@link #status(String, String)}). */
    public JobImage image(String id, String principal) {
        RenderJob job = local(id, principal);
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

    /** A finished job's image and status. */
    public record JobImage(JobStatus status, byte[] bytes) {
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
        RenderJob job = local(id, principal);
        if (job == null) {
            if (!cluster.subscribe(id, principal, listener, senders)) {
                throw new JobNotFoundException(id);
            }
            return;
        }
        int listeners = 0;
        for (RenderJob each : jobs.values()) {
            listeners += each.subscriptionCount();
        }
        if (listeners >= MAX_LISTENERS) {
            throw new JobQueueFullException(retryAfterSeconds(), "the server has as many event streams open as it "
                    + "serves (" + MAX_LISTENERS + "); poll the job's status instead, or try again shortly");
        }
        job.subscribe(listener, senders);
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
        jobs.remove(job.id());
        job.release();
        cluster.dropped(job.id());
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

    /**
     * Stops taking jobs (new ones get 429) and cancels the queued ones at once; their listeners hear the end.
     * In a cluster, the unfinished jobs, queued and running, are handed to the other members instead.
     */
    @Override
    public void stopAccepting() {
        executor.shutdown();
        executor.getQueue().clear();
        List<RenderJob> unfinished = jobs.values().stream().filter(job -> !job.state().isFinal()).toList();
        if (cluster.canHandOver()) {
            String reason = "handed over to another member";
            // clients first (they hear no end from here), then the cluster stops the renders, then they end here
            unfinished.forEach(job -> job.handingOver(reason));
            cluster.handOver(unfinished.stream().map(RenderJob::id).collect(java.util.stream.Collectors.toSet()));
            unfinished.forEach(job -> job.cancel(reason));
            handedOver.addAll(unfinished);
            return;
        }
        for (RenderJob job : jobs.values()) {
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
                jobs.remove(job.id());
                job.release();
            }
            handedOver.clear();
        }
        return ended;
    }

    /** Cancels the jobs still running (they stop within a tile) and waits for that as {@link #awaitEnd}. */
    @Override
    public void cancelRunning(long deadlineNanos) throws InterruptedException {
        for (RenderJob job : jobs.values()) {
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
            for (RenderJob job : jobs.values()) {
                heard &= !job.state().isFinal() || !job.hasSubscriptions();
            }
            if (heard) {
                return;
            }
            Thread.sleep(10);
        }
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

package studio.server.job;

import java.util.List;
import java.util.Map;
import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

import studio.engine.render.Film;
import studio.engine.render.RenderCancelledException;
import studio.engine.render.RenderListener;
import studio.engine.render.RenderResult;
import studio.engine.render.TileRect;
import studio.server.render.ImageFiles;
import studio.server.render.RenderBudget;
import studio.server.render.RenderMetrics;
import studio.server.render.RenderTimeExceededException;
import studio.server.scene.compiling.CompiledScene;
import studio.server.system.MemoryBudget;

/**
 * One render job's state machine: its scene, state, progress and, when done, the encoded image,
 * and the memory it holds (the render's while queued or running, then the image's). State changes
 * are made under the job's lock and appended to its {@link JobEvents}, which listeners hear off the
 * lock and off the render threads, in order. A finished job lets go of its scene.
 */
final class RenderJob implements Runnable {

    /** How the job's tiles get rendered: on this member's pool, or by the cluster's members. */
    @FunctionalInterface
    interface Render {
        RenderResult render(CompiledScene scene, RenderListener listener, BooleanSupplier cancelled);
    }

    /**
     * Who learns a job's end before the job itself reports it (see {@link JobCluster#ending}): called on
     * the job's thread, holding no lock, once the render is over and before the job's status turns final.
     */
    @FunctionalInterface
    interface Ending {
        Ending NONE = (end, image) -> {
        };

        /** @param image the encoded image when {@code end} is done, else null */
        void ending(JobStatus end, byte[] image);
    }

    private final String id;
    /** Who submitted the job ("" with sign-in off): only they see it. */
    private final String principal;
    /** Null once the job is final. */
    private CompiledScene scene;
    private final int width, height;
    private final String fileName, mediaType;
    private final RenderBudget budget;
    private final Render render;
    private final Ending ending;
    /** The tiles each member rendered (in a cluster), else null. */
    private final Supplier<Map<String, Integer>> workers;
    /** The render's memory while it is queued or running; then the image's, until the job is dropped. */
    private MemoryBudget.Reservation memory;
    private final AtomicBoolean cancelRequested = new AtomicBoolean();
    private final JobEvents events = new JobEvents();
    private int tileCount;
    private final long createdNanos = System.nanoTime();

    private JobState state = JobState.QUEUED;
    private double progress;
    private long startNanos, endNanos;
    private Double raysPerSecond;
    private String error;
    /** Why a cancel was asked for, if it was. */
    private String cancelReason = "cancelled";
    private byte[] image;
    /** When someone last asked about this job (status, events, image); see {@link JobService}. */
    private volatile long lastSeenNanos = System.nanoTime();

    RenderJob(String id, CompiledScene scene, RenderBudget budget, MemoryBudget.Reservation memory) {
        this(id, "", scene, budget, memory,
                (compiled, listener, cancelled) -> budget.render(compiled.request().heardBy(listener).cancelledWhen(cancelled)),
                () -> null, Ending.NONE);
    }

    RenderJob(String id, String principal, CompiledScene scene, RenderBudget budget, MemoryBudget.Reservation memory,
              Render render, Supplier<Map<String, Integer>> workers, Ending ending) {
        this.id = id;
        this.principal = principal;
        this.render = render;
        this.ending = ending;
        this.workers = workers;
        this.scene = scene;
        this.width = scene.settings().width();
        this.height = scene.settings().height();
        this.fileName = scene.fileName();
        this.mediaType = scene.mediaType();
        this.budget = budget;
        this.memory = memory;
    }

    String id() {
        return id;
    }

    String principal() {
        return principal;
    }

    @Override
    public void run() {
        CompiledScene scene;
        JobStatus cancelledBeforeStart = null;
        synchronized (this) {
            if (state != JobState.QUEUED) {
                return;
            }
            if (cancelRequested.get()) {
                finish(JobState.CANCELLED, cancelReason + " before it started");
                cancelledBeforeStart = status();
                scene = null;
            } else {
                state = JobState.RUNNING;
                scene = this.scene;
                startNanos = System.nanoTime();
                broadcastStatus();
            }
        }
        if (cancelledBeforeStart != null) {
            JobLog.ended(cancelledBeforeStart, 0);
            return;
        }
        JobLog.started(id, (startNanos - createdNanos) / 1_000_000);
        try {
            RenderResult result = render.render(scene, this::tileFinished, cancelRequested::get);
            budget.metrics().rendered(RenderMetrics.Kind.JOB, result);
            byte[] bytes = ImageFiles.encode(result.film(), scene.format(), scene.quality());
            end(JobState.DONE, null, bytes, result.raysPerSecond());
        } catch (RenderCancelledException e) {
            end(JobState.CANCELLED, cancelReason(), null, null);
        } catch (RenderTimeExceededException | JobFailedException e) {
            end(JobState.FAILED, e.getMessage(), null, null);
        } catch (RuntimeException | OutOfMemoryError e) {
            end(JobState.FAILED, "the render failed: " + e.getClass().getSimpleName(), null, null);
        }
    }

    /**
     * Ends a job that ran: tells {@link Ending} its end first, outside the lock, and only then turns
     * final, so that nobody hears the end from this job before those told first have it. The image
     * is here before that: whoever heard the end from them gets the image from this job too.
     */
    private void end(JobState finalState, String message, byte[] bytes, Double rays) {
        long endAt = System.nanoTime();
        JobStatus end;
        synchronized (this) {
            image = bytes;
            end = status(finalState, message, endAt, rays);
        }
        try {
            ending.ending(end, bytes);
        } catch (RuntimeException e) {
            // those told first learn the end from the job's events instead
        }
        synchronized (this) {
            raysPerSecond = rays;
            finish(finalState, message, endAt);
        }
        JobLog.ended(end, bytes != null ? bytes.length : 0);
    }

    private synchronized String cancelReason() {
        return cancelReason;
    }

    private void tileFinished(Film film, TileRect tile, int done, int total) {
        String png = TilePng.encode(film, tile);
        synchronized (this) {
            if (state.isFinal()) {
                return; // a tile that finished after the job ended (cancelled) is not news
            }
            // the tiles recorded, not the renderer's count: with several threads a later count can
            // arrive here first, and progress would step back, or run ahead of what a late client replays
            progress = (double) ++tileCount / total;
            events.add(new TileEvent(tile.x(), tile.y(), tile.width(), tile.height(), png, progress));
        }
    }

    /** Asks the job to stop; a queued job is cancelled at once, a running one after its current tiles. */
    JobStatus cancel() {
        return cancel("cancelled");
    }

    /** As {@link #cancel()}, with the reason the job's status will give. */
    JobStatus cancel(String reason) {
        JobStatus status;
        boolean endedNow = false;
        synchronized (this) {
            if (!cancelRequested.getAndSet(true)) {
                cancelReason = reason;
            }
            if (state == JobState.QUEUED) {
                finish(JobState.CANCELLED, cancelReason + " before it started");
                endedNow = true;
            }
            status = status();
        }
        if (endedNow) {
            JobLog.ended(status, 0);
        }
        return status;
    }

    /**
     * The job is about to go on on another member (this one is stopping): its clients (not the
     * cluster's listener) are dropped, so that they reconnect through another member, and when it stops here ({@link #cancel(String)}
     * follows) it says why. What it tells the cluster is up to the cluster: nothing, for a job handed over.
     */
    void handingOver(String reason) {
        synchronized (this) {
            if (!cancelRequested.get()) {
                cancelReason = reason;
            }
        }
        events.dropClients(); // the cluster's own listener stops when the cluster says so
    }

    /** Marks a job the executor refused or dropped. */
    void fail(String message) {
        JobStatus status = null;
        synchronized (this) {
            if (!state.isFinal()) {
                finish(JobState.FAILED, message);
                status = status();
            }
        }
        if (status != null) {
            JobLog.ended(status, 0);
        }
    }

    private void finish(JobState finalState, String message) {
        finish(finalState, message, System.nanoTime());
    }

    private void finish(JobState finalState, String message, long endAt) {
        state = finalState;
        error = message;
        endNanos = endAt;
        scene = null;
        // the render's memory is free now; the image, already made, is counted until the job is dropped
        MemoryBudget.Reservation rendering = memory;
        memory = image != null ? budget.memory().forceReserve(image.length) : null;
        if (rendering != null) {
            rendering.close();
        }
        events.ended(status());
    }

    /**
     * Registers a listener: its sender delivers the status, every tile so far, then what follows,
     * and last the end.
     */
    JobSubscription subscribe(JobListener listener, Executor sender) {
        return subscribe(listener, sender, false);
    }

    /**
     * As {@link #subscribe(JobListener, Executor)}; an {@code internal} listener (the one that tells
     * the cluster) is no client: it does not count as one watching the job.
     */
    synchronized JobSubscription subscribe(JobListener listener, Executor sender, boolean internal) {
        touch();
        return events.subscribe(listener, sender, internal, status());
    }

    /** Drops a subscription that fell behind; the job goes on. */
    void drop(JobSubscription subscription) {
        events.drop(subscription);
    }

    /** The subscriptions whose deliveries have not returned for {@code nanos}. */
    List<JobSubscription> stalled(long nanos, long now) {
        return events.stalled(nanos, now);
    }

    void unsubscribe(JobListener listener) {
        events.unsubscribe(listener);
        touch();
    }

    /** Removes the listener; true if it was the last one of an unfinished job. */
    boolean unsubscribeLast(JobListener listener) {
        return events.unsubscribeLast(listener);
    }

    /** Gives back the memory the job holds (it is being dropped, or was never started). */
    synchronized void release() {
        if (memory != null) {
            memory.close();
            memory = null;
        }
    }

    void heartbeat() {
        events.heartbeat();
    }

    /** The clients' subscriptions (not the cluster's). */
    int subscriptionCount() {
        return events.clients();
    }

    /** Whether a client (not the cluster) watches the job. */
    boolean hasListeners() {
        return events.clients() > 0;
    }

    /** Whether any subscription, the cluster's too, has yet to hear the end. */
    boolean hasSubscriptions() {
        return events.hasSubscriptions();
    }

    private void broadcastStatus() {
        events.add(status());
    }

    synchronized JobStatus status() {
        return status(state, error, endNanos != 0 ? endNanos : System.nanoTime(), raysPerSecond);
    }

    /** The status the job has (or will have) in {@code state}, at {@code endAt} (System.nanoTime). */
    private JobStatus status(JobState state, String error, long endAt, Double raysPerSecond) {
        long elapsed = startNanos != 0 ? (endAt - startNanos) / 1_000_000 : 0;
        return new JobStatus(id, state, state == JobState.DONE ? 1.0 : progress, elapsed, raysPerSecond,
                width, height, fileName, mediaType, error, workers.get());
    }

    synchronized JobState state() {
        return state;
    }

    /**
     * The encoded image, or null unless done (or about to be: it is here while the job's end is being
     * told, see {@link Ending}).
     */
    synchronized byte[] image() {
        return image;
    }

    synchronized long finishedNanos() {
        return endNanos;
    }

    void touch() {
        lastSeenNanos = System.nanoTime();
    }

    long lastSeenNanos() {
        return lastSeenNanos;
    }
}

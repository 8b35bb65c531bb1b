package studio.server.job;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;

import javax.imageio.ImageIO;

import studio.engine.image.ImageEncoder;
import studio.engine.render.Film;
import studio.engine.render.RenderCancelledException;
import studio.engine.render.RenderResult;
import studio.engine.render.TileRect;
import studio.server.render.ImageFiles;
import studio.server.render.RenderBudget;
import studio.server.render.RenderTimeExceededException;
import studio.server.scene.CompiledScene;
import studio.server.system.MemoryBudget;

/**
 * One render job: its scene, state, progress, the tiles finished so far (for clients that
 * connect late) and, when done, the encoded image. State changes and events happen under the
 * job's lock, so every listener sees them in order. A finished job lets go of its scene: it is
 * kept for a while only for its status and image.
 */
final class RenderJob implements Runnable {

    private final String id;
    /** Null once the job is final. */
    private CompiledScene scene;
    private final int width, height;
    private final String fileName, mediaType;
    private final RenderBudget budget;
    /** The render's memory while it is queued or running; then the image's, until the job is dropped. */
    private MemoryBudget.Reservation memory;
    private final AtomicBoolean cancelRequested = new AtomicBoolean();
    private final List<TileEvent> tiles = new ArrayList<>();
    private final List<JobListener> listeners = new ArrayList<>();
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
        this.id = id;
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

    @Override
    public void run() {
        CompiledScene scene;
        synchronized (this) {
            if (state != JobState.QUEUED) {
                return;
            }
            if (cancelRequested.get()) {
                finish(JobState.CANCELLED, cancelReason + " before it started");
                return;
            }
            state = JobState.RUNNING;
            scene = this.scene;
            startNanos = System.nanoTime();
            broadcastStatus();
        }
        try {
            RenderResult result = budget.render(scene, this::tileFinished, cancelRequested::get);
            byte[] bytes = ImageFiles.encode(result.film(), scene.format(), scene.quality());
            synchronized (this) {
                image = bytes;
                raysPerSecond = result.raysPerSecond();
                finish(JobState.DONE, null);
            }
        } catch (RenderCancelledException e) {
            synchronized (this) {
                finish(JobState.CANCELLED, cancelReason);
            }
        } catch (RenderTimeExceededException e) {
            synchronized (this) {
                finish(JobState.FAILED, e.getMessage());
            }
        } catch (RuntimeException | OutOfMemoryError e) {
            synchronized (this) {
                finish(JobState.FAILED, "the render failed: " + e.getClass().getSimpleName());
            }
        }
    }

    private void tileFinished(Film film, TileRect tile, int done, int total) {
        String png = tilePng(film, tile);
        synchronized (this) {
            if (state.isFinal()) {
                return; // a tile that finished after the job ended (cancelled) is not news
            }
            // the tiles recorded, not the renderer's count: with several threads a later count can
            // arrive here first, and progress would step back, or run ahead of what a late client replays
            progress = (double) (tiles.size() + 1) / total;
            TileEvent event = new TileEvent(tile.x(), tile.y(), tile.width(), tile.height(), png, progress);
            tiles.add(event);
            for (JobListener listener : List.copyOf(listeners)) {
                listener.tile(event);
            }
        }
    }

    /** Asks the job to stop; a queued job is cancelled at once, a running one after its current tiles. */
    synchronized JobStatus cancel() {
        return cancel("cancelled");
    }

    /** As {@link #cancel()}, with the reason the job's status will give. */
    synchronized JobStatus cancel(String reason) {
        if (!cancelRequested.getAndSet(true)) {
            cancelReason = reason;
        }
        if (state == JobState.QUEUED) {
            finish(JobState.CANCELLED, cancelReason + " before it started");
        }
        return status();
    }

    /** Marks a job the executor refused or dropped. */
    synchronized void fail(String message) {
        if (!state.isFinal()) {
            finish(JobState.FAILED, message);
        }
    }

    private void finish(JobState finalState, String message) {
        state = finalState;
        error = message;
        endNanos = System.nanoTime();
        scene = null;
        tiles.clear();
        // the render's memory is free now; the image, already made, is counted until the job is dropped
        MemoryBudget.Reservation rendering = memory;
        memory = image != null ? budget.memory().forceReserve(image.length) : null;
        if (rendering != null) {
            rendering.close();
        }
        JobStatus status = status();
        for (JobListener listener : List.copyOf(listeners)) {
            listener.end(status);
        }
        listeners.clear();
    }

    /** Registers a listener: it first hears the status and every tile so far, then what follows. */
    synchronized void subscribe(JobListener listener) {
        touch();
        JobStatus status = status();
        listener.status(status);
        if (state.isFinal()) {
            listener.end(status);
            return;
        }
        for (TileEvent tile : tiles) {
            listener.tile(tile);
        }
        listeners.add(listener);
    }

    synchronized void unsubscribe(JobListener listener) {
        listeners.remove(listener);
        touch();
    }

    /** Removes the listener; true if it was the last one of an unfinished job. */
    synchronized boolean unsubscribeLast(JobListener listener) {
        boolean removed = listeners.remove(listener);
        return removed && listeners.isEmpty() && !state.isFinal();
    }

    /** Gives back the memory the job holds (it is being dropped, or was never started). */
    synchronized void release() {
        if (memory != null) {
            memory.close();
            memory = null;
        }
    }

    synchronized void heartbeat() {
        for (JobListener listener : List.copyOf(listeners)) {
            listener.heartbeat();
        }
    }

    synchronized boolean hasListeners() {
        return !listeners.isEmpty();
    }

    private void broadcastStatus() {
        JobStatus status = status();
        for (JobListener listener : List.copyOf(listeners)) {
            listener.status(status);
        }
    }

    synchronized JobStatus status() {
        long end = endNanos != 0 ? endNanos : System.nanoTime();
        long elapsed = startNanos != 0 ? (end - startNanos) / 1_000_000 : 0;
        return new JobStatus(id, state, state == JobState.DONE ? 1.0 : progress, elapsed, raysPerSecond,
                width, height, fileName, mediaType, error);
    }

    synchronized JobState state() {
        return state;
    }

    /** The encoded image, or null unless done. */
    synchronized byte[] image() {
        return image;
    }

    synchronized long finishedNanos() {
        return endNanos;
    }

    long createdNanos() {
        return createdNanos;
    }

    void touch() {
        lastSeenNanos = System.nanoTime();
    }

    long lastSeenNanos() {
        return lastSeenNanos;
    }

    /** One tile of the film as a base64 PNG. */
    static String tilePng(Film film, TileRect tile) {
        var whole = ImageEncoder.toImage(film, tile);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            ImageIO.write(whole, "png", out);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return Base64.getEncoder().encodeToString(out.toByteArray());
    }
}

package studio.server.render;

import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

import studio.engine.render.RenderCancelledException;
import studio.engine.render.RenderResult;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.system.Drainable;
import studio.server.system.IntakeMemory;
import studio.server.system.MemoryBudget;

/**
 * Renders scenes for the synchronous API: at most a configured number at once, each within the
 * {@link RenderBudget}, on the service's own render threads, so that the HTTP thread is free and a
 * client that goes away can cancel its render ({@link Ticket#cancel()}).
 */
public final class RenderService implements Drainable, AutoCloseable {

    private final SceneCompiler compiler;
    private final Semaphore slots;
    private final int threads;
    private final RenderBudget budget;
    private final ExecutorService executor;
    private final Set<Ticket> running = ConcurrentHashMap.newKeySet();
    private final AtomicLong cancelledCount = new AtomicLong();
    private volatile boolean closed;

    /**
     * @param concurrentRenders renders allowed at once; more are refused ({@link RenderBusyException})
     * @param threads           worker threads per render, 0 for all cores
     */
    public RenderService(SceneCompiler compiler, int concurrentRenders, int threads, RenderBudget budget) {
        this.compiler = compiler;
        this.slots = new Semaphore(concurrentRenders);
        this.threads = threads;
        this.budget = budget;
        AtomicInteger count = new AtomicInteger();
        this.executor = Executors.newFixedThreadPool(concurrentRenders, r -> {
            Thread t = new Thread(r, "render-" + count.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
    }

    public RenderService(SceneCompiler compiler, int concurrentRenders, int threads) {
        this(compiler, concurrentRenders, threads, RenderBudget.unlimited());
    }

    /**
     * Validates the scene and starts its render.
     *
     * @throws studio.server.scene.format.InvalidSceneException if the scene is invalid or could never fit the memory budget
     * @throws RenderBusyException if every slot, or the memory the render needs, is taken right now
     */
    public Ticket start(byte[] sceneJson) {
        return start(sceneJson, ClientProbe.NONE, IntakeMemory.NONE);
    }

    /**
     * As {@link #start(byte[])}; the render also stops when {@code client} finds its client gone.
     * The slot is taken before the scene is read, so that a refused request costs no reading (many
     * clients sending large scenes at once to few slots get their 503s at once). The price, as for jobs: while every
     * slot is busy, an invalid scene, too, is answered 503 first, and its 400 comes on the retry.
     * The compile draws on the request's {@code intake}, which hands it over to the render's memory.
     */
    public Ticket start(byte[] sceneJson, ClientProbe client, IntakeMemory intake) {
        if (closed) {
            throw new RenderBusyException("the server is shutting down; try again shortly");
        }
        if (!slots.tryAcquire()) {
            throw new RenderBusyException();
        }
        CompiledScene compiled;
        MemoryBudget.Reservation memory;
        try {
            compiled = compiler.compile(CompileRequest.of(sceneJson).onThreads(threads).within(intake));
            memory = budget.reserve(compiled, intake);
        } catch (RuntimeException | Error e) {
            slots.release();
            throw e;
        }
        if (memory == null) {
            slots.release();
            throw new RenderBusyException("the server's render memory is taken by other renders right now; try again "
                    + "shortly");
        }
        Ticket ticket = new Ticket(compiled, memory, client);
        running.add(ticket);
        try {
            executor.execute(ticket::run);
        } catch (RejectedExecutionException e) {
            ticket.finish();
            throw new RenderBusyException("the server is shutting down; try again shortly");
        }
        return ticket;
    }

    /** Renders running or about to run. */
    public int active() {
        return running.size();
    }

    /** Renders stopped because their client went away (or the server stopped), since the start. */
    public long cancelled() {
        return cancelledCount.get();
    }

    /** How long a client may have to wait: the time budget, with a minute for queueing and encoding. */
    public long responseTimeoutMillis() {
        return budget.maxTime().toMillis() + 60_000;
    }

    /** Refuses new renders from now on (503 with Retry-After); the running ones go on. */
    @Override
    public void stopAccepting() {
        closed = true;
        executor.shutdown();
    }

    /** Waits until the running renders have ended, at most until the deadline; true if they all did. */
    @Override
    public boolean awaitEnd(long deadlineNanos) throws InterruptedException {
        return executor.awaitTermination(Math.max(0, deadlineNanos - System.nanoTime()), TimeUnit.NANOSECONDS);
    }

    /** Cancels the running renders (their clients get 503 with Retry-After) and waits as {@link #awaitEnd}. */
    @Override
    public void cancelRunning(long deadlineNanos) throws InterruptedException {
        for (Ticket ticket : running) {
            ticket.cancel();
        }
        awaitEnd(deadlineNanos);
    }

    /**
     * Refuses new renders, lets the running ones finish for up to {@code graceMillis}, then cancels them
     * and waits for that, at most {@value Drainable#CANCEL_WAIT_MILLIS} ms more.
     */
    public void shutdown(long graceMillis) {
        Drainable.drain(List.of(this), graceMillis);
        executor.shutdownNow();
    }

    @Override
    public void close() {
        shutdown(0);
    }

    /** One synchronous render: its result when it ends, and a way to stop it. */
    public final class Ticket {
        private final CompiledScene scene;
        private final MemoryBudget.Reservation memory;
        private final ClientProbe client;
        private final AtomicBoolean cancelRequested = new AtomicBoolean();
        private final CompletableFuture<RenderedImage> result = new CompletableFuture<>();
        private final AtomicBoolean finished = new AtomicBoolean();

        private Ticket(CompiledScene scene, MemoryBudget.Reservation memory, ClientProbe client) {
            this.scene = scene;
            this.memory = memory;
            this.client = client;
        }

        /** The image, or the failure: {@link RenderTimeExceededException}, {@link RenderCancelledException}, ... */
        public CompletableFuture<RenderedImage> result() {
            return result;
        }

        /** Stops the render within a few milliseconds (a no-op once it has ended). */
        public void cancel() {
            cancelRequested.set(true);
        }

        /** Asked by the render every few milliseconds: a cancel, or a client that went away. */
        private boolean stopRequested() {
            if (!cancelRequested.get() && client.gone()) {
                cancelRequested.set(true);
            }
            return cancelRequested.get();
        }

        /**
         * Renders and encodes, gives back the slot and the memory, then answers: a client that asks
         * again as soon as it has its image finds them free (answered first, its next request, or a
         * live view's next frame, could be refused for the memory of the render it already has).
         */
        private void run() {
            RenderedImage image = null;
            Throwable failure = null;
            try {
                if (cancelRequested.get()) {
                    throw new RenderCancelledException();
                }
                RenderResult rendered = budget.render(scene.request().cancelledWhen(this::stopRequested));
                budget.metrics().rendered(RenderMetrics.Kind.SYNC, rendered);
                byte[] bytes = ImageFiles.encode(rendered.film(), scene.format(), scene.quality());
                image = new RenderedImage(bytes, scene.mediaType(), scene.fileName(), scene.settings().width(),
                        scene.settings().height(), rendered.elapsedMillis(), rendered.raysPerSecond());
            } catch (RenderCancelledException e) {
                cancelledCount.incrementAndGet();
                failure = e;
            } catch (RuntimeException | Error e) {
                failure = e;
            } finally {
                finish();
            }
            if (failure == null) {
                result.complete(image);
            } else {
                result.completeExceptionally(failure);
            }
        }

        private void finish() {
            if (finished.compareAndSet(false, true)) {
                running.remove(this);
                memory.close();
                slots.release();
            }
        }
    }
}

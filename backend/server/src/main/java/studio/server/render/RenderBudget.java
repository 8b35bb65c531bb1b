package studio.server.render;

import java.time.Duration;
import java.util.function.BooleanSupplier;
import java.util.function.Function;

import studio.engine.render.RenderCancelledException;
import studio.engine.render.RenderResult;
import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.format.InvalidSceneException;
import studio.server.system.IntakeMemory;
import studio.server.system.MemoryBudget;

/**
 * What one render may use: at most {@code maxTime} of wall time (asked every few milliseconds, as
 * cancellation is: the render stops within a camera sample of its deadline) and its share of the
 * service's {@link MemoryBudget}; and where the renders that finished are counted
 * ({@link RenderMetrics}, by whoever asked for the render).
 */
public final class RenderBudget {

    private final Duration maxTime;
    private final MemoryBudget memory;
    private final RenderMetrics metrics;

    /** A budget whose renders are counted in memory only. */
    public RenderBudget(Duration maxTime, MemoryBudget memory) {
        this(maxTime, memory, RenderMetrics.unpublished());
    }

    public RenderBudget(Duration maxTime, MemoryBudget memory, RenderMetrics metrics) {
        if (maxTime.isNegative() || maxTime.isZero()) {
            throw new IllegalArgumentException("the time budget per render must be positive: " + maxTime);
        }
        this.maxTime = maxTime;
        this.memory = memory;
        this.metrics = metrics;
    }

    /** No time limit to speak of, and no memory limit (tests, the command line). */
    public static RenderBudget unlimited() {
        return new RenderBudget(Duration.ofDays(365), MemoryBudget.unlimited());
    }

    public Duration maxTime() {
        return maxTime;
    }

    public MemoryBudget memory() {
        return memory;
    }

    public RenderMetrics metrics() {
        return metrics;
    }

    /**
     * Reserves the render's memory.
     *
     * @return the reservation, or null if the memory is taken by other work right now
     * @throws InvalidSceneException if the render could never fit into the budget
     */
    public MemoryBudget.Reservation reserve(CompiledScene scene) {
        return reserve(scene, IntakeMemory.NONE);
    }

    /**
     * Reserves the render's memory in the same step in which the request that compiled the scene
     * gives back what compiling it took ({@link IntakeMemory#handOver}), so that a scene whose
     * compile and render together exceed the budget can still run.
     *
     * @return the reservation, or null if the memory is taken by other work right now
     * @throws InvalidSceneException if the render could never fit into the budget
     */
    public MemoryBudget.Reservation reserve(CompiledScene scene, IntakeMemory compiledWith) {
        long bytes = RenderMemory.estimate(scene);
        if (bytes > memory.capacity()) {
            throw new InvalidSceneException("image", "this scene needs about " + RenderMemory.mebibytes(bytes)
                    + " MiB to render (" + scene.settings().width() + "x" + scene.settings().height()
                    + " pixels and its objects), more than this server's render memory of "
                    + RenderMemory.mebibytes(memory.capacity()) + " MiB (studio.render-memory); make the image "
                    + "or the meshes smaller");
        }
        return compiledWith.handOver(memory, bytes);
    }

    /**
     * Renders what {@code request} asks (see {@link Renderer#render}) within the time budget.
     *
     * @throws RenderCancelledException    if the request's {@code cancelled} turned true first
     * @throws RenderTimeExceededException if the budget ran out first
     */
    public RenderResult render(RenderRequest request) {
        return withinTime(request.cancelled(), stop -> Renderer.render(request.cancelledWhen(stop)));
    }

    /**
     * Runs {@code render} (given a condition that turns true on cancel or at the deadline) within
     * the time budget: a render of tiles that other machines render, too.
     *
     * @throws RenderCancelledException    if {@code cancelled} turned true first
     * @throws RenderTimeExceededException if the budget ran out first
     */
    public RenderResult withinTime(BooleanSupplier cancelled, Function<BooleanSupplier, RenderResult> render) {
        long deadline = System.nanoTime() + maxTime.toNanos();
        try {
            return render.apply(() -> cancelled.getAsBoolean() || System.nanoTime() - deadline > 0);
        } catch (RenderCancelledException e) {
            if (!cancelled.getAsBoolean() && System.nanoTime() - deadline > 0) {
                throw new RenderTimeExceededException(maxTime);
            }
            throw e;
        }
    }

    /** 90 s, 5 min, 1 h 30 min: a duration as a person writes it. */
    static String describe(Duration d) {
        long seconds = d.toSeconds();
        if (seconds < 120) {
            return d.toMillis() % 1000 == 0 ? seconds + " s" : d.toMillis() + " ms";
        }
        if (seconds < 7200) {
            return seconds % 60 == 0 ? seconds / 60 + " min" : seconds / 60 + " min " + seconds % 60 + " s";
        }
        return seconds / 3600 + " h" + (seconds % 3600 / 60 != 0 ? " " + seconds % 3600 / 60 + " min" : "");
    }
}

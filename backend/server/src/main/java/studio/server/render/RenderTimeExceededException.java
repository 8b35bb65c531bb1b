package studio.server.render;

import java.time.Duration;

/** A render ran longer than this server's time budget per render and was stopped. */
public final class RenderTimeExceededException extends RuntimeException {

    public RenderTimeExceededException(Duration budget) {
        super("the render was stopped after " + RenderBudget.describe(budget) + ", this server's time budget per "
                + "render (studio.limits.max-render-time); lower render.samples, the image size or render.maxDepth");
    }
}

package studio.server.preview;

import java.util.ArrayList;
import java.util.List;

import studio.engine.render.RenderSettings;

/**
 * One pass of the live view's refinement: a render of the scene at some size and samples per pixel.
 *
 * @param number   1 for the coarsest pass
 * @param settings the pass's render settings
 * @param last     true for the pass that renders exactly what {@code POST /api/render} would
 */
record PreviewPass(int number, RenderSettings settings, boolean last) {

    /** Coarse passes render the view at these fractions of its size, one sample a pixel, before the full size. */
    static final int[] COARSE_DIVISORS = {8, 4, 2};

    /**
     * The passes for a scene whose own settings (at the view's size) are {@code target}: 1/8, 1/4,
     * 1/2 of the size at one sample a pixel, then the full size at one sample, then the target
     * itself, skipping passes no smaller or cheaper than the next.
     */
    static List<PreviewPass> plan(RenderSettings target) {
        List<PreviewPass> passes = new ArrayList<>();
        for (int divisor : COARSE_DIVISORS) {
            int width = Math.max(1, target.width() / divisor), height = Math.max(1, target.height() / divisor);
            if (width * 2 <= target.width() && passes.stream().noneMatch(p -> p.settings().width() == width)) {
                passes.add(new PreviewPass(passes.size() + 1, oneSample(target, width, height), false));
            }
        }
        boolean oneSampleIsTarget = target.sampler().samplesPerPixel() == 1;
        if (!oneSampleIsTarget) {
            passes.add(new PreviewPass(passes.size() + 1, oneSample(target, target.width(), target.height()), false));
        }
        passes.add(new PreviewPass(passes.size() + 1, target, true));
        return passes;
    }

    /** The target's camera, depth and seed at another size, one sample a pixel, not adaptive. */
    private static RenderSettings oneSample(RenderSettings target, int width, int height) {
        return new RenderSettings(width, height, target.sampler().withSamplesPerPixel(1), target.maxDepth(),
                target.threads(), target.seed(), target.minPathWeight(), 0);
    }
}

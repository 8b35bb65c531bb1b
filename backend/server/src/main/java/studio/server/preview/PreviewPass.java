package studio.server.preview;

import java.util.ArrayList;
import java.util.List;

import studio.engine.render.PixelLattice;
import studio.engine.render.RenderSettings;
import studio.engine.sampler.Sampler;

/**
 * One pass of the live view's refinement: a render of some of the view's pixels at some samples
 * per pixel. The passes before the last are a mosaic: the view at one sample a pixel, rendered
 * into one film lattice by lattice (one pixel of each 8x8 block, then the rest of every fourth,
 * every second and every pixel), so each coarse frame costs only its new pixels and the
 * full-size one-sample frame costs one one-sample render in all (an earlier plan rendered 1/8,
 * 1/4 and 1/2 size images from scratch before it: a third more work and three more encodings).
 *
 * @param number   1 for the coarsest pass
 * @param settings the render settings of the film the pass renders into (the whole view's size)
 * @param pixels   the pixels this pass's frame shows, a lattice of the film
 * @param except   the pixels already rendered into the film by the pass before (null: none)
 * @param last     true for the pass that renders exactly what {@code POST /api/render} would
 */
record PreviewPass(int number, RenderSettings settings, PixelLattice pixels, PixelLattice except, boolean last) {

    /** The mosaic's coarse lattices, coarsest first: one pixel of each block of this side. */
    static final int[] COARSE_STEPS = {8, 4, 2};

    /** This pass's frame width: the lattice's columns. */
    int frameWidth() {
        return pixels.count(settings.width());
    }

    /** This pass's frame height: the lattice's rows. */
    int frameHeight() {
        return pixels.count(settings.height());
    }

    /**
     * The passes for a scene whose own settings (at the view's size) are {@code target}: the
     * mosaic at one sample a pixel, its coarsest lattice at the centre of its blocks (so the
     * coarse image is not shifted against the fine ones) and the finer ones at their corners, a
     * lattice kept only if its frame is at most half the view's size and not the size of the one
     * before; then the target itself, unless the one-sample film already is the target.
     */
    static List<PreviewPass> plan(RenderSettings target) {
        int width = target.width(), height = target.height();
        RenderSettings oneSample = oneSample(target);
        List<PreviewPass> passes = new ArrayList<>();
        PixelLattice before = null;
        for (int step : COARSE_STEPS) {
            PixelLattice lattice = new PixelLattice(step, before == null ? step / 2 : 0);
            int w = lattice.count(width), h = lattice.count(height);
            boolean coarser = w >= 1 && h >= 1 && w * 2 <= width;
            boolean sameSize = before != null && before.count(width) == w && before.count(height) == h;
            if (coarser && !sameSize) {
                passes.add(new PreviewPass(passes.size() + 1, oneSample, lattice, before, false));
                before = lattice;
            }
        }
        // a target at one sample a pixel renders the same with or without a threshold (RenderSettings.adaptive)
        boolean oneSampleIsTarget = oneSample.equals(target.withAdaptiveThreshold(0));
        passes.add(new PreviewPass(passes.size() + 1, oneSample, PixelLattice.ALL, before, oneSampleIsTarget));
        if (!oneSampleIsTarget) {
            passes.add(new PreviewPass(passes.size() + 1, target, PixelLattice.ALL, null, true));
        }
        return passes;
    }

    /** The target's camera, size, depth and seed at one sample a pixel, not adaptive. */
    private static RenderSettings oneSample(RenderSettings target) {
        return new RenderSettings(target.width(), target.height(), Sampler.of(target.sampler().name(), 1),
                target.maxDepth(), target.threads(), target.seed(), target.minPathWeight(), 0);
    }
}

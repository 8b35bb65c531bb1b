package studio.engine.render;

import studio.engine.sampler.PixelRandom;

/**
 * Russian roulette on the weak branches of a glass surface's split. A branch (the reflection or
 * the refraction) whose path weight is below {@link #BELOW} is traced with probability
 * weight / BELOW and then counted BELOW / weight times, so each sample's expected value is what
 * tracing every branch gives, while the long chains of faint reflections inside glass (4% of 4%
 * of ...) are mostly not traced. The split itself stays: a branch at or above the threshold is
 * always traced, so at normal incidence both the refraction and the 4% reflection are.
 *
 * <p>{@link #BELOW} is where time against error was best on glass-pattern and the bench's glass
 * (docs/speed.md): above it the noise it adds costs the adaptive sampler more samples than the
 * roulette saves, and choosing one branch by its Fresnel weight tripled the 16-sample error.
 *
 * <p>The numbers are drawn from a stream of their own per pixel sample, seeded from the pixel, the
 * sample's index and the render's seed, and only when a branch is weak: a pixel comes out the same
 * to the bit whichever thread or cluster member renders it, and a scene without glass draws none.
 * One per worker thread.
 */
final class BranchRoulette {

    /** Branches with a path weight below this play the roulette; measured, see above. */
    static final double BELOW = 0.05;
    /** Mixed with the sample's index into the render's seed, so these numbers are not the sampler's. */
    private static final long SAMPLE_SALT = 0x632be59bd9b4e019L;

    private final double below;
    private final long seed;
    private final PixelRandom random = new PixelRandom();
    private int x, y, sample;
    /** Whether the current sample's stream has been started (lazily, by its first draw). */
    private boolean started;

    /** Roulette below {@code below} (0: none, every branch is traced), with the render's seed. */
    BranchRoulette(double below, long seed) {
        if (!(below >= 0 && below <= 1)) {
            throw new IllegalArgumentException("the roulette's threshold is a path weight in [0, 1]: " + below);
        }
        this.below = below;
        this.seed = seed;
    }

    /** No roulette: every branch is traced. */
    static BranchRoulette none() {
        return new BranchRoulette(0, 0);
    }

    /** The next draws belong to sample {@code sample} of pixel (x, y). */
    void startSample(int x, int y, int sample) {
        this.x = x;
        this.y = y;
        this.sample = sample;
        started = false;
    }

    /**
     * How many times a branch of path weight {@code weight} counts: 1 at or above the threshold;
     * below it, threshold / weight with probability weight / threshold, otherwise 0 (not traced).
     */
    double factor(double weight) {
        if (weight >= below) {
            return 1;
        }
        if (!started) {
            random.reset(x, y, seed ^ SAMPLE_SALT * (sample + 1L));
            started = true;
        }
        return random.nextDouble() * below < weight ? below / weight : 0;
    }
}

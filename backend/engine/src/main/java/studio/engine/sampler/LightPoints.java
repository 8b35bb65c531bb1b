package studio.engine.sampler;

/**
 * The 2D point each camera sample gives its light samples (where on a sphere or area light its
 * shadow rays go), taken from the pixel sampler's own points: a run of samples first .. first +
 * count - 1 gets the run's own pixel points, shuffled by a pixel-seeded permutation (as pbrt-v3's
 * stratified sampler pads further dimensions with shuffled copies of its strata). So the light
 * points are as well spread over [0, 1)^2 as the pixel points are (one per stratum of a jittered
 * pattern, a (0, m, 2)-net for a Sobol run of 2^m from 2^m), more pixel samples mean better light
 * samples, the sample's place in the pixel and on the light are not tied together, and every
 * pixel's points are the same at any thread count. One per worker thread; allocates nothing after
 * construction.
 */
public final class LightPoints {

    /** Sets the light stream apart from the pixel sampler's stream of the same pixel. */
    private static final long STREAM = 0x6c62272e07bb0142L;

    private final long seed;
    private final PixelRandom random = new PixelRandom();
    private final int[] order;
    private int first;

    /** @param samplesPerPixel the longest run a pixel traces */
    public LightPoints(int samplesPerPixel, long seed) {
        this.order = new int[Math.max(1, samplesPerPixel)];
        this.seed = seed;
    }

    /** Shuffles the run first .. first + count - 1 of pixel (x, y)'s samples. */
    public void start(int x, int y, int first, int count) {
        this.first = first;
        random.reset(x, y, seed ^ STREAM);
        random.skip((long) first << 24);
        for (int i = 0; i < count; i++) {
            int j = random.nextInt(i + 1); // Fisher-Yates, inside out
            order[i] = order[j];
            order[j] = first + i;
        }
    }

    /** Which pixel point of the run sample s takes as its light point: read xs and ys at this index. */
    public int of(int s) {
        return order[s - first];
    }
}

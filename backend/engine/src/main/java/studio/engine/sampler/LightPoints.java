package studio.engine.sampler;

/**
 * The 2D point each camera sample gives its light samples (where on a sphere or area light its
 * shadow rays go). A run of samples first .. first + count - 1 gets one stratified pattern of count
 * points, dealt out to the run's samples by a pixel-seeded permutation (as pbrt-v3's stratified
 * sampler pads further dimensions with shuffled copies of its strata), so the sample's place in the
 * pixel and on the light are not tied together and every pixel's points are the same at any thread
 * count. The pattern is the run's own pixel points, except under the jittered sampler: there it is a
 * multi-jittered pattern of the run's size ({@link MultiJitteredSampler}), which has jittered's
 * cells and also one point in each of N narrow columns and rows, so a shadow edge across the light
 * is cut into N strata, not sqrt(N) (PenumbraTest's wall at 64 jittered samples: 0.08 of random's
 * squared error, 0.51 with the pixel's own points shuffled). A Sobol run of 2^k from 2^k is a
 * (0, k, 2)-net already, and the runs of one pixel together are the sequence's first points, so
 * sobol keeps its own points. One per worker thread; allocates nothing after construction.
 */
public final class LightPoints {

    /** Sets the light stream apart from the pixel sampler's stream of the same pixel. */
    private static final long STREAM = 0x6c62272e07bb0142L;

    private final long seed;
    /** Whether the run's pattern is a multi-jittered one of its own (under jittered) rather than the pixel's points. */
    private final boolean ownPattern;
    private final MultiJitteredSampler multiJittered;
    private final PixelRandom random = new PixelRandom();
    private final int[] order;
    private final double[] patternU, patternV, us, vs;
    private int first;

    /**
     * @param pixelSampler the render's sampler: its samples per pixel are the longest run a pixel traces
     */
    public LightPoints(Sampler pixelSampler, long seed) {
        int most = Math.max(1, pixelSampler.samplesPerPixel());
        this.order = new int[most];
        this.patternU = new double[most];
        this.patternV = new double[most];
        this.us = new double[most];
        this.vs = new double[most];
        this.seed = seed;
        this.ownPattern = pixelSampler instanceof JitteredSampler;
        this.multiJittered = new MultiJitteredSampler(most);
    }

    /**
     * Deals the light points of the run first .. first + count - 1 of pixel (x, y), whose pixel
     * points are xs and ys at the same indices.
     */
    public void start(int x, int y, int first, int count, double[] xs, double[] ys) {
        this.first = first;
        if (count == 1 && !ownPattern) { // a run of one deals its one pixel point to itself
            us[0] = xs[first];
            vs[0] = ys[first];
            return;
        }
        random.reset(x, y, seed ^ STREAM);
        random.skip((long) first << 24);
        if (count == 0) {
            return;
        }
        if (ownPattern) {
            multiJittered.fill(random, count, 0, count, patternU, patternV);
        } else {
            System.arraycopy(xs, first, patternU, 0, count);
            System.arraycopy(ys, first, patternV, 0, count);
        }
        for (int i = 0; i < count; i++) {
            int j = random.nextInt(i + 1); // Fisher-Yates, inside out
            order[i] = order[j];
            order[j] = i;
        }
        for (int i = 0; i < count; i++) {
            us[i] = patternU[order[i]];
            vs[i] = patternV[order[i]];
        }
    }

    /** Sample s's light point's first coordinate, in [0, 1). */
    public double u(int s) {
        return us[s - first];
    }

    /** Sample s's light point's second coordinate, in [0, 1). */
    public double v(int s) {
        return vs[s - first];
    }
}

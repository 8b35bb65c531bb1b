package studio.engine.sampler;

import java.util.Arrays;

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
 * sobol keeps its own points. Its runs of 2 and 4 (a refined pixel's samples 2-3 and 4-7) pair them
 * by strata instead of shuffling: the sample in x's cell c of the run (a 1 / count-wide column,
 * one point each) gets the point in cell reverse(c) xor 1, so every half of x meets every half (of 2)
 * or quarter (of 4) of u; with samples 0 and 1, each its own point, a pixel's first 4 samples cover
 * all 4 pairs of halves of (x, u) and of (y, v), where a shuffle left them on the diagonal half the
 * time; pairing longer runs too raised the error at many samples (docs/speed.md, "Soft lights").
 * One per worker thread; allocates nothing after construction.
 */
public final class LightPoints {

    /** Sets the light stream apart from the pixel sampler's stream of the same pixel. */
    private static final long STREAM = 0x6c62272e07bb0142L;

    private final long seed;
    /** Whether the run's pattern is a multi-jittered one of its own (under jittered) rather than the pixel's points. */
    private final boolean ownPattern;
    private final MultiJitteredSampler multiJittered;
    /** Whether the pixel's points are Sobol's, whose runs of up to {@value #PAIRED_MOST} are paired by strata. */
    private final boolean sobol;
    static final int PAIRED_MOST = 4;
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
        this.sobol = pixelSampler instanceof SobolSampler;
    }

    /**
     * Deals the light points of the run first .. first + count - 1 of pixel (x, y), whose pixel
     * points are xs and ys at the same indices.
     */
    public void start(int x, int y, int first, int count, double[] xs, double[] ys) {
        this.first = first;
        if (sobol && (count == 2 || count == PAIRED_MOST) && first % count == 0 && pairByCells(first, count, xs, ys)) {
            return;
        }
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

    /**
     * Deals the run's point in x's cell reverse(c) xor 1 to the sample in cell c (see the class
     * comment); false, dealing nothing, if two of the run's points share a cell (not a net).
     */
    private boolean pairByCells(int first, int count, double[] xs, double[] ys) {
        Arrays.fill(order, 0, count, -1);
        for (int j = 0; j < count; j++) {
            int cell = (int) (xs[first + j] * count);
            if (order[cell] >= 0) {
                return false;
            }
            order[cell] = j;
        }
        int shift = 32 - Integer.numberOfTrailingZeros(count);
        for (int i = 0; i < count; i++) {
            int cell = (int) (xs[first + i] * count);
            int j = order[(Integer.reverse(cell) >>> shift) ^ 1];
            us[i] = xs[first + j];
            vs[i] = ys[first + j];
        }
        return true;
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

package studio.engine.sampler;

/**
 * A pixel's samples by index, as pbrt-v4's {@code StartPixelSample(pixel, sampleIndex)}: after
 * {@link #startPixel}, any run of the pixel's samples can be asked for, in any order, and sample i
 * is always the same. One per worker thread; it allocates nothing after construction.
 *
 * <p>The pixel's samples are consecutive patterns of the sampler, each of {@code patternSize}
 * samples (the last of the rest, when the samples per pixel are not a multiple): one pattern of all
 * N for fixed and progressive sampling, patterns of 4 for batch-adaptive sampling. Sample i is
 * element i mod size of pattern i / size, and pattern p draws its random values from the pixel's
 * stream after the p full patterns before it: exactly where drawing the patterns one after the
 * other leaves the stream, reached with one {@link PixelRandom#skip}. Asking for a run costs that
 * run (plus, with multi-jittered, the rest of its patterns), never the samples before it. Measured
 * at 16 samples a pixel in batches of 4, finding each pattern's start (a reset and a skip) and
 * copying it out costs 4-15 ns a sample more than drawing the patterns from one continuing stream
 * did, against 450-700 ns for tracing a sample of a small glass-and-mirror scene; whole renders at
 * 320x240 showed no difference beyond their noise.
 */
public final class PixelSamples {

    private final Sampler sampler;
    private final int samplesPerPixel, patternSize, patternDraws;
    private final long seed;
    private final PixelRandom random = new PixelRandom();
    /** One pattern's samples, before they are copied to the pixel's indices. */
    private final double[] patternXs, patternYs;
    private int x, y;
    /**
     * Whether the pixel's samples are one Sobol pattern of more than one point: then its three seeds
     * are drawn once a pixel ({@link #seeded}) and every run costs its points alone, where drawing
     * them again for each of a refined pixel's runs (1, 1, 2, 4, ...) took a fifth of the Sobol time.
     */
    private final boolean onePatternSobol;
    private boolean seeded;
    private int indexSeed, xSeed, ySeed;

    /**
     * @param patternSize the samples of one pattern (at least 1); at least the samples per pixel
     *                    for one pattern per pixel
     * @param seed        the render's seed
     */
    public PixelSamples(Sampler sampler, int patternSize, long seed) {
        if (patternSize < 1) {
            throw new IllegalArgumentException("a pattern needs at least one sample: " + patternSize);
        }
        this.sampler = sampler;
        this.samplesPerPixel = sampler.samplesPerPixel();
        this.patternSize = Math.min(patternSize, samplesPerPixel);
        this.patternDraws = sampler.draws(this.patternSize);
        this.seed = seed;
        patternXs = new double[this.patternSize];
        patternYs = new double[this.patternSize];
        onePatternSobol = sampler instanceof SobolSampler && this.patternSize == samplesPerPixel && samplesPerPixel > 1;
    }

    /** The most samples a pixel has: indices run from 0 to this minus 1. */
    public int samplesPerPixel() {
        return samplesPerPixel;
    }

    /** Makes pixel (x, y) the one whose samples {@link #fill} gives. */
    public void startPixel(int x, int y) {
        this.x = x;
        this.y = y;
        seeded = false;
    }

    /**
     * Samples first .. first + count - 1 of the pixel into xs and ys at the same indices.
     *
     * @throws IndexOutOfBoundsException unless 0 &lt;= first &lt;= first + count &lt;= samples per pixel
     */
    public void fill(int first, int count, double[] xs, double[] ys) {
        int end = first + count;
        if (first < 0 || count < 0 || end > samplesPerPixel) {
            throw new IndexOutOfBoundsException("samples " + first + " to " + (end - 1) + " of " + samplesPerPixel);
        }
        if (onePatternSobol) {
            if (!seeded) { // as SobolSampler.fill draws them for pattern 0
                random.reset(x, y, seed);
                indexSeed = random.nextInt();
                xSeed = random.nextInt();
                ySeed = random.nextInt();
                seeded = true;
            }
            SobolSampler.points(indexSeed, xSeed, ySeed, first, count, xs, ys);
            return;
        }
        for (int i = first; i < end; ) {
            int pattern = i / patternSize, start = pattern * patternSize;
            int size = Math.min(patternSize, samplesPerPixel - start), stop = Math.min(end, start + size);
            random.reset(x, y, seed);
            random.skip((long) pattern * patternDraws);
            sampler.fill(random, size, i - start, stop - i, patternXs, patternYs);
            System.arraycopy(patternXs, i - start, xs, i, stop - i);
            System.arraycopy(patternYs, i - start, ys, i, stop - i);
            i = stop;
        }
    }
}

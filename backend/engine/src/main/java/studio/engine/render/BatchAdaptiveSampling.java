package studio.engine.render;

import studio.engine.sampler.PixelSamples;

/**
 * Adaptive sampling in batches (every sampler but sobol; threshold t &gt; 0). With N the sampler's
 * samples per pixel (the maximum), a pixel takes samples in batches of {@value #BATCH}, each a fresh
 * pattern of the configured sampler (so each batch is stratified): its samples 4j .. 4j + 3 are
 * pattern j of the pixel's {@link PixelSamples}. After each full batch, with k the number of full batches so far,
 * n = {@value #BATCH} k the samples so far, and per channel c (linear light):
 * <ul>
 * <li>m_c,j the mean of batch j and M_c = mean_j m_c,j (the pixel's mean),</li>
 * <li>SE_c = sqrt(sum_j (m_c,j - M_c)^2 / (k (k - 1))), the standard error of M_c from the batch means,</li>
 * <li>R_c = (largest - smallest sample in channel c) / n: the step one sample moving across the
 *     samples' range makes in the mean,</li>
 * </ul>
 * the pixel stops when
 * <pre>
 *     k &gt;= {@value #MIN_BATCHES}  and  for every c: max(SE_c, R_c) &lt;= L,   L = t * sqrt(max(max_c M_c, 1/255))
 * </pre>
 * i.e. every channel's error is within t times the square root of the brightest channel's mean
 * (see {@link TileSampling#limitOf}). The R_c term is there because with stratified batches and two
 * or three batches a pixel cut by an edge often has identical batch means (SE = 0) by chance; the
 * mean of n two-valued samples cannot be trusted to better than one sample's step. Otherwise the
 * pixel stops at N samples; if N is not a multiple of {@value #BATCH}, the last batch is a pattern of
 * N mod {@value #BATCH} samples. A pixel therefore takes at least min(N, {@value #MIN_BATCHES} x
 * {@value #BATCH}) samples: a flat pixel stops there; edges, shadow borders, highlights and
 * reflections take more. The pixel's value is the mean of all its samples. The rule uses only the
 * pixel's own samples, so the image is the same at any thread count.
 */
final class BatchAdaptiveSampling implements TileSampling {

    /** Samples per batch. */
    public static final int BATCH = 4;
    /** A pixel takes at least this many batches (if the maximum allows). */
    public static final int MIN_BATCHES = 2;

    private final SampleTracer tracer;
    private final int max;
    /** The pixel's samples in patterns of one batch. */
    private final PixelSamples pixelSamples;
    private final double[] xs, ys;
    private final double threshold;
    private long samples;

    BatchAdaptiveSampling(RenderSettings settings, SampleTracer tracer) {
        this.tracer = tracer;
        max = settings.sampler().samplesPerPixel();
        pixelSamples = new PixelSamples(settings.sampler(), BATCH, settings.seed());
        xs = new double[max];
        ys = new double[max];
        threshold = settings.adaptiveThreshold();
    }

    @Override
    public long render(TileRequest request) {
        Film film = request.film();
        TileRect tile = request.tile();
        long bad = 0;
        for (int y = tile.y(); y < tile.y() + tile.height(); y++) {
            for (int x = tile.x(); x < tile.x() + tile.width(); x++) {
                pixelSamples.startPixel(x, y);
                bad += pixel(film, x, y);
            }
        }
        return bad;
    }

    @Override
    public long samples() {
        return samples;
    }

    /** Batches of {@link #BATCH} samples until the pixel's estimate is good enough. */
    private long pixel(Film film, int x, int y) {
        SampleTracer t = tracer;
        long bad = 0;
        int taken = 0, batches = 0;
        double totalR = 0, totalG = 0, totalB = 0;
        // Welford's running mean and sum of squared deviations of the full batches' means, per channel.
        double meanR = 0, meanG = 0, meanB = 0, m2R = 0, m2G = 0, m2B = 0;
        t.resetRange();
        while (taken < max) {
            int size = Math.min(BATCH, max - taken);
            pixelSamples.fill(taken, size, xs, ys);
            bad += t.trace(x, y, xs, ys, taken, size);
            taken += size;
            totalR += t.sumR;
            totalG += t.sumG;
            totalB += t.sumB;
            if (size < BATCH) {
                break; // the partial batch is the last one
            }
            batches++;
            double r = t.sumR / BATCH, g = t.sumG / BATCH, b = t.sumB / BATCH;
            double dR = r - meanR, dG = g - meanG, dB = b - meanB;
            meanR += dR / batches;
            meanG += dG / batches;
            meanB += dB / batches;
            m2R += dR * (r - meanR);
            m2G += dG * (g - meanG);
            m2B += dB * (b - meanB);
            if (batches >= MIN_BATCHES) {
                double limit = TileSampling.limitOf(threshold, Math.max(meanR, Math.max(meanG, meanB)));
                double step = t.widestRange() / taken;
                // standard error^2 = m2 / (k (k - 1)) <= limit^2, and one sample's step <= limit
                if (Math.max(m2R, Math.max(m2G, m2B)) <= limit * limit * batches * (batches - 1)
                        && step <= limit) {
                    break;
                }
            }
        }
        samples += taken;
        film.set(x, y, totalR / taken, totalG / taken, totalB / taken);
        return bad;
    }
}

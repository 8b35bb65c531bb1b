package studio.engine.render;

import studio.engine.sampler.PixelSamples;

/**
 * Adaptive sampling with the {@code sobol} sampler: one scrambled Sobol sequence per pixel, walked
 * in two passes over each tile. First every pixel takes {@value #BASE} sample, and so does a ring of
 * {@value TileBorders#LINES} pixels around the tile (the ring's samples are the same its own tiles
 * take; with {@link TileBorders} tiles on one machine share them instead of tracing them twice). A
 * pixel's 3 x 3 neighbourhood <em>agrees</em> when its 9 base samples do (at least
 * {@value #FIRST_JUDGED} where the image's border cuts it; a lone pixel's never does): per channel c,
 * (largest - smallest of them) / {@value #BASE} &lt;= L, with L from the pixel's own mean (see
 * {@link TileSampling#limitOf}). An edge, shadow or speck that crosses a pixel nearly always
 * separates some of these samples: the neighbours find what the pixel's own sample misses, much as
 * POV-Ray's adaptive anti-aliasing compares the pixel corners it shares with its neighbours. A pixel
 * stops at {@value #BASE} if its neighbourhood agrees and so do its 8 neighbours', or if only
 * theirs differ by a step S (the widest range of base samples in any of them) so small that
 * S / ({@value #NEARBY_SHARE_INVERSE} m) &lt;= L', m the samples of its own neighbourhood and L' the
 * limit of the brighter of its mean and S. The neighbours' neighbourhoods matter in a penumbra,
 * where every sample is lit or shadowed: near the umbra 9 samples are all shadowed by chance (for a
 * pixel that sees a tenth of the light, 0.9^9 = 39% of the time), and the pixel would stop at the
 * umbra's value at any threshold. From threshold 0.035 up (the default is 0.05) S / 36 &lt;= L' and,
 * below, S / 32 &lt;= L' hold for any step up to white away from the image's border: only pixels
 * beside a light seen or on the border change there (11 of 19,200 on a held-out scene at 0.05).
 * Under a sphere or area light a base sample also tells an umbra from a penumbra: where a convex
 * object stopped its shadow ray but does not hide the whole light ({@link ShadowRays#seesPart}), its
 * point sees part of the light, and its pixel does not stop at its base sample however its
 * neighbourhood agrees; the light it could add there, counted whole as S, keeps it sampling until
 * that over n is within the limit. Where a floor sees a sliver of a light, all the base samples near
 * a pixel are often dark by chance, and it stopped at black (robustness case LIGHT-06).
 * Otherwise the pixel walks on along its sequence to {@value #FIRST_JUDGED} samples, then doubles:
 * after n = 2^k samples (8, 16, ...) the means A_c of the first and B_c of the second n/2 samples are
 * both estimates from a stratified (0, k-1, 2)-net, and the pixel stops when
 * <pre>
 *     for every c: |A_c - B_c| / 2 &lt;= L,   R / n &lt;= L   and   S / ({@value #NEARBY_SHARE_INVERSE} n) &lt;= L'
 * </pre>
 * else at N (in a scene with a sphere or area light, judged first at 4, with |A_c - B_c| / 3 and
 * R / 2n, every L at half the threshold: {@link #SOFT_FIRST_JUDGED}, and the halves' L growing as
 * sqrt(n / 4), so that a pixel takes samples in proportion to its samples' spread rather than its
 * square: the least squared error over the image for its samples gives each pixel samples in
 * proportion to its spread). R is the widest channel's range of the pixel's n samples: two halves of a few
 * stratified samples can agree by chance on an edge. S is the step next to it: where all n samples
 * agree, a part of the pixel (or of the light) of about 1/n that none of them reached may still hold
 * it, so a pixel beside an edge or a penumbra takes samples in proportion to S / L', and a lower
 * threshold always buys more of them. L' is the limit of the brighter of the mean and S: the hidden
 * part would bring the pixel that far, and judged by a black pixel's own limit every black pixel
 * beside a white edge went to the maximum. Independent batches would lose the stratification (their
 * error falls like N^-1/2); halves of one sequence keep it, so the estimate and the image both
 * improve like a fixed-count Sobol pattern. Every decision reads only samples seeded by pixel, so the
 * image is the same at any thread count, and whichever worker renders which tile.
 *
 * <p>Why (the speed-accuracy bench, docs/speed.md): one base sample instead of 4 saves most where
 * pixels are flat; judging a refined pixel's halves from 2 samples instead of {@value #FIRST_JUDGED}
 * stalls the error on edges (two samples on one side agree); without S the error stops falling as
 * the threshold does, held by penumbra pixels whose few samples were all shadowed by chance.
 */
final class ProgressiveSobolSampling implements TileSampling {

    /** The samples every pixel takes before it is judged by its neighbourhood. */
    public static final int BASE = 1;
    /** The samples a pixel its neighbourhood did not settle takes before its halves are compared. */
    public static final int FIRST_JUDGED = 4;
    /**
     * In a scene with a sphere or area light: the samples a refined pixel takes before its halves are
     * first compared (2 against 2; elsewhere 4 against 4), the share of their difference that counts
     * (|A - B| / 3; elsewhere / 2) and of their range (R / (2n); elsewhere R / n), and the threshold's
     * share in every limit ({@link #SOFT_THRESHOLD_SHARE}). A penumbra pixel's samples differ by light
     * sample as well as by place in the pixel, and a base sample's neighbourhood finds that in every
     * pixel near it; those whose first 4 samples agree stop there (fewer samples to jittered's
     * 16-sample error on the soft-light chart, docs/speed.md).
     */
    static final int SOFT_FIRST_JUDGED = 2, SOFT_HALVES_SHARE = 3, SOFT_RANGE_SHARE_INVERSE = 2;
    /**
     * The threshold's share in a soft-light scene's limits: with the laxer tests above at the whole
     * threshold, the default threshold's error would rise by half; at half of it, it is as before, in
     * fewer samples (the soft-light chart, docs/speed.md).
     */
    static final double SOFT_THRESHOLD_SHARE = 0.5;
    /**
     * S's share in the step n agreeing samples may hide (see the class comment). On soft-ball and
     * soft-room at 160x120 a quarter and an eighth give the same curve; the whole step spends up to
     * a third more samples at thresholds 0.02 to 0.01 for the same error.
     */
    static final int NEARBY_SHARE_INVERSE = 4;
    /** The ring of pixels around a tile whose base samples the tile reads. */
    private static final int RING = TileBorders.LINES;
    /** A tile of the usual size with its ring: the buffers' first size. */
    private static final int RING_TILE = RenderSettings.TILE_SIZE + 2 * RING;

    private final SampleTracer tracer;
    /** Where tiles share their edge pixels' base samples, or null: each tile traces its ring itself. */
    private final TileBorders borders;
    private final StopSignal stop;
    /** The pixel's samples: one pattern, the sequence's first N points. */
    private final PixelSamples pixelSamples;
    /**
     * Each base pixel's sum and per-channel range, over a tile and its ring. Sized for a tile of the
     * usual size, and grown once for a larger one (a cluster's tiles are 64 pixels a side).
     */
    private double[] baseSum = new double[3 * RING_TILE * RING_TILE];
    private double[] baseMin = new double[3 * RING_TILE * RING_TILE], baseMax = new double[3 * RING_TILE * RING_TILE];
    /** Per channel, the smallest and largest base sample of each pixel and its left and right neighbours. */
    private double[] rowMin = new double[3 * RING_TILE * RING_TILE], rowMax = new double[3 * RING_TILE * RING_TILE];
    /**
     * For each pixel of the tile and a one-pixel ring: its 3 x 3 neighbourhood's step (see
     * {@link #neighbourhoodStep}), and whether the neighbourhood agrees.
     */
    private double[] step = new double[RING_TILE * RING_TILE];
    private boolean[] agrees = new boolean[RING_TILE * RING_TILE];
    /** For each pixel of the tile and its ring: {@link SampleTracer#penumbraLight} of its base samples. */
    private double[] penumbra = new double[RING_TILE * RING_TILE];
    private final double[] xs, ys;
    private final int max, width, height;
    private final double threshold;
    /** The samples a refined pixel's first step reaches, when its halves are first judged, and R's share (see {@link #SOFT_FIRST_JUDGED}). */
    private final int firstStep, firstJudged, halvesShare, rangeShareInverse;
    /** Whether the scene has a sphere or area light: then base samples watch for penumbrae, and the halves' limit grows. */
    private final boolean soft;
    private long samples;

    ProgressiveSobolSampling(RenderSettings settings, SampleTracer tracer, TileBorders borders, StopSignal stop) {
        this.tracer = tracer;
        this.borders = borders;
        this.stop = stop;
        if (!settings.adaptive()) {
            throw new IllegalArgumentException("adaptive sampling needs a threshold and more than one sample a pixel");
        }
        max = settings.sampler().samplesPerPixel();
        pixelSamples = new PixelSamples(settings.sampler(), max, settings.seed());
        xs = new double[max];
        ys = new double[max];
        width = settings.width();
        height = settings.height();
        soft = tracer.softLights();
        threshold = soft ? settings.adaptiveThreshold() * SOFT_THRESHOLD_SHARE : settings.adaptiveThreshold();
        firstStep = soft ? SOFT_FIRST_JUDGED : FIRST_JUDGED;
        firstJudged = soft ? 2 * SOFT_FIRST_JUDGED : 2 * FIRST_JUDGED;
        halvesShare = soft ? SOFT_HALVES_SHARE : 2;
        rangeShareInverse = soft ? SOFT_RANGE_SHARE_INVERSE : 1;
    }

    /** Grows the tile buffers to hold {@code length} values (once per tile size larger than any before). */
    private void fit(int length) {
        if (baseSum.length < length) {
            baseSum = new double[length];
            baseMin = new double[length];
            baseMax = new double[length];
            rowMin = new double[length];
            rowMax = new double[length];
            step = new double[length / 3];
            agrees = new boolean[length / 3];
            penumbra = new double[length / 3];
        }
    }

    @Override
    public long samples() {
        return samples;
    }

    /**
     * First every pixel of the tile and of its ring takes {@value #BASE} samples (whichever tile
     * takes an edge pixel's first leaves them in the borders for the other); then each pixel of the
     * tile stops there if its own and its neighbours' 3 x 3 neighbourhoods agree, else walks on.
     */
    @Override
    public long render(TileRequest request) {
        Film film = request.film();
        TileRect tile = request.tile();
        int x0 = Math.max(0, tile.x() - RING), y0 = Math.max(0, tile.y() - RING);
        int x1 = Math.min(width, tile.x() + tile.width() + RING), y1 = Math.min(height, tile.y() + tile.height() + RING);
        int stride = x1 - x0;
        fit(3 * stride * (y1 - y0));
        int base = BASE; // below max: a pixel may take more than one sample (see the constructor)
        SampleTracer t = tracer;
        long bad = 0;
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                int i = (y - y0) * stride + x - x0;
                int entry = borders == null ? -1 : borders.entryOf(x, y);
                long badHere = entry < 0 ? -1 : borders.loadOrClaim(entry, baseSum, baseMin, baseMax, 3 * i, stop);
                if (badHere >= 0) {
                    penumbra[i] = borders.penumbraLight(entry);
                } else {
                    pixelSamples.startPixel(x, y);
                    pixelSamples.fill(0, base, xs, ys);
                    t.resetRange();
                    t.watchPenumbrae(soft);
                    try {
                        // bundled whatever the count: the pass goes along rows, so one listing serves 4 pixels (docs/speed.md)
                        badHere = t.trace(x, y, xs, ys, 0, base, true);
                    } catch (RuntimeException | Error e) {
                        if (entry >= 0) {
                            borders.abandon(entry);
                        }
                        throw e;
                    } finally {
                        t.watchPenumbrae(false); // refinement samples do not ask
                    }
                    penumbra[i] = t.penumbraLight();
                    baseSum[3 * i] = t.sumR;
                    baseSum[3 * i + 1] = t.sumG;
                    baseSum[3 * i + 2] = t.sumB;
                    baseMin[3 * i] = t.minR; baseMin[3 * i + 1] = t.minG; baseMin[3 * i + 2] = t.minB;
                    baseMax[3 * i] = t.maxR; baseMax[3 * i + 1] = t.maxG; baseMax[3 * i + 2] = t.maxB;
                    if (entry >= 0) {
                        borders.store(entry, baseSum, baseMin, baseMax, 3 * i, (int) badHere, penumbra[i]);
                    }
                }
                if (tile.contains(x, y)) {
                    bad += badHere;
                }
            }
        }
        // the tile and a one-pixel ring: whether each pixel's neighbourhood agrees
        int jx0 = Math.max(0, tile.x() - 1), jy0 = Math.max(0, tile.y() - 1);
        int jx1 = Math.min(width, tile.x() + tile.width() + 1), jy1 = Math.min(height, tile.y() + tile.height() + 1);
        rowRanges(jx0, jx1, x0, x1, y0, y1);
        for (int y = jy0; y < jy1; y++) {
            int rows = (y > y0 ? 1 : 0) + 1 + (y + 1 < y1 ? 1 : 0);
            for (int x = jx0; x < jx1; x++) {
                int i = (y - y0) * stride + x - x0;
                double brightest = higher(baseSum[3 * i], higher(baseSum[3 * i + 1], baseSum[3 * i + 2])) / base;
                int columns = (x > x0 ? 1 : 0) + 1 + (x + 1 < x1 ? 1 : 0);
                step[i] = neighbourhoodStep(i, stride, y > y0, y + 1 < y1, rows * columns * base, base);
                agrees[i] = step[i] <= TileSampling.limitOf(threshold, brightest);
            }
        }
        for (int y = tile.y(); y < tile.y() + tile.height(); y++) {
            int top = Math.max(jy0, y - 1), bottom = Math.min(jy1 - 1, y + 1);
            for (int x = tile.x(); x < tile.x() + tile.width(); x++) {
                int i = (y - y0) * stride + x - x0;
                int left = Math.max(jx0, x - 1), right = Math.min(jx1 - 1, x + 1);
                boolean settled = true;
                double nearby = 0;
                for (int v = top; v <= bottom; v++) {
                    for (int u = left; u <= right; u++) {
                        int q = (v - y0) * stride + u - x0;
                        settled &= agrees[q];
                        if (step[q] != Double.POSITIVE_INFINITY) {
                            nearby = higher(nearby, step[q]);
                        }
                    }
                }
                double span = nearby * base;
                if (penumbra[i] > 0) {
                    // its base sample's point sees part of a light its shadow ray missed: the light counts
                    // whole as the step its samples may all have missed (S / 4n = light / n)
                    settled = false;
                    span = higher(span, NEARBY_SHARE_INVERSE * penumbra[i]);
                } else if (!settled && agrees[i]) {
                    // only a neighbour's neighbourhood differs: what the samples of this one may have missed
                    double brightest = higher(baseSum[3 * i], higher(baseSum[3 * i + 1], baseSum[3 * i + 2])) / base;
                    int judged = (bottom - top + 1) * (right - left + 1) * base;
                    settled = span / NEARBY_SHARE_INVERSE / judged <= TileSampling.limitOf(threshold, higher(brightest, span));
                }
                if (settled) {
                    samples += base;
                    film.set(x, y, baseSum[3 * i] / base, baseSum[3 * i + 1] / base, baseSum[3 * i + 2] / base);
                } else {
                    bad += refinePixel(film, x, y, i, base, span);
                }
            }
        }
        return bad;
    }

    /**
     * For every row of the ring at columns jx0 .. jx1 - 1, each channel's smallest and largest base
     * sample of the pixel and its left and right neighbours (as far as the ring, x0 .. x1 - 1, goes):
     * the first half of the 3 x 3 neighbourhood's ranges, which {@link #neighbourhoodStep} finishes
     * over three rows. Split so, the test reads 12 values a pixel per channel instead of 18.
     */
    private void rowRanges(int jx0, int jx1, int x0, int x1, int y0, int y1) {
        int stride = x1 - x0;
        for (int y = y0; y < y1; y++) {
            for (int x = jx0; x < jx1; x++) {
                int i = 3 * ((y - y0) * stride + x - x0);
                int left = x > x0 ? i - 3 : i, right = x + 1 < x1 ? i + 3 : i;
                for (int c = 0; c < 3; c++) {
                    rowMin[i + c] = lower(baseMin[left + c], lower(baseMin[i + c], baseMin[right + c]));
                    rowMax[i + c] = higher(baseMax[left + c], higher(baseMax[i + c], baseMax[right + c]));
                }
            }
        }
    }

    /**
     * The step one base sample makes in a mean, across pixel i's 3 x 3 neighbourhood (the rows
     * above and below if the ring has them): the range of all their base samples in the channel
     * where it is widest, over {@code base}; infinite when the neighbourhood (cut by the image's
     * border) holds fewer than {@value #FIRST_JUDGED} samples to judge by, as a lone pixel's one
     * sample, whose range is always 0.
     */
    private double neighbourhoodStep(int i, int stride, boolean above, boolean below, int samples, int base) {
        if (samples < FIRST_JUDGED) {
            return Double.POSITIVE_INFINITY;
        }
        int j = 3 * i, up = above ? j - 3 * stride : j, down = below ? j + 3 * stride : j;
        double spanR = higher(rowMax[up], higher(rowMax[j], rowMax[down]))
                - lower(rowMin[up], lower(rowMin[j], rowMin[down]));
        double spanG = higher(rowMax[up + 1], higher(rowMax[j + 1], rowMax[down + 1]))
                - lower(rowMin[up + 1], lower(rowMin[j + 1], rowMin[down + 1]));
        double spanB = higher(rowMax[up + 2], higher(rowMax[j + 2], rowMax[down + 2]))
                - lower(rowMin[up + 2], lower(rowMin[j + 2], rowMin[down + 2]));
        return Math.max(spanR, Math.max(spanG, spanB)) / base;
    }

    /**
     * The smaller of two values that are never NaN: a plain comparison, without Math.min's care for
     * NaN and -0.0 (with the test's 54 Math.min and Math.max calls a pixel it had 3,825 JFR samples of
     * 15,630 on edges at most 2 samples; with plain comparisons 2,991; split as well, it is no longer
     * among the hot frames).
     */
    private static double lower(double a, double b) {
        return b < a ? b : a;
    }

    /** The larger of two values that are never NaN (see {@link #lower}). */
    private static double higher(double a, double b) {
        return b > a ? b : a;
    }

    /**
     * Walks on along pixel i's sequence from its {@code base} samples to {@value #FIRST_JUDGED}, then
     * doubling, until the halves agree, its samples' range over n is within its limit and {@code span}
     * (S of the class comment) over {@value #NEARBY_SHARE_INVERSE} n within the limit of the brighter
     * of its mean and S, or the maximum is reached.
     */
    private long refinePixel(Film film, int x, int y, int i, int base, double span) {
        SampleTracer t = tracer;
        pixelSamples.startPixel(x, y);
        t.minR = baseMin[3 * i]; t.minG = baseMin[3 * i + 1]; t.minB = baseMin[3 * i + 2];
        t.maxR = baseMax[3 * i]; t.maxG = baseMax[3 * i + 1]; t.maxB = baseMax[3 * i + 2];
        double totalR = baseSum[3 * i], totalG = baseSum[3 * i + 1], totalB = baseSum[3 * i + 2];
        long bad = 0;
        int taken = base;
        while (taken < max) {
            double firstR = totalR, firstG = totalG, firstB = totalB;
            int half = taken, target = Math.min(max, Math.max(taken * 2, firstStep));
            pixelSamples.fill(taken, target - taken, xs, ys);
            bad += t.trace(x, y, xs, ys, taken, target - taken, true);
            totalR += t.sumR;
            totalG += t.sumG;
            totalB += t.sumB;
            taken = target;
            if (taken < max && half * 2 == taken && taken >= firstJudged) {
                double dR = Math.abs(firstR - (totalR - firstR)) / half;
                double dG = Math.abs(firstG - (totalG - firstG)) / half;
                double dB = Math.abs(firstB - (totalB - firstB)) / half;
                double mean = Math.max(totalR, Math.max(totalG, totalB)) / taken;
                double limit = TileSampling.limitOf(threshold, mean);
                // under soft light the halves' limit grows as sqrt(n): samples in proportion to the spread, not its square
                double halvesLimit = soft ? limit * Math.sqrt((double) taken / firstJudged) : limit;
                double step = t.widestRange() / rangeShareInverse / taken;
                double nearbyStep = span / NEARBY_SHARE_INVERSE / taken;
                double nearbyLimit = TileSampling.limitOf(threshold, higher(mean, span));
                if (Math.max(dR, Math.max(dG, dB)) / halvesShare <= halvesLimit && step <= limit && nearbyStep <= nearbyLimit) {
                    break;
                }
            }
        }
        samples += taken;
        film.set(x, y, totalR / taken, totalG / taken, totalB / taken);
        return bad;
    }
}

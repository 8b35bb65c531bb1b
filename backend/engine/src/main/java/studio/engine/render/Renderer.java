package studio.engine.render;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.BooleanSupplier;

import studio.engine.camera.Camera;
import studio.engine.geometry.Ray;
import studio.engine.sampler.PixelRandom;
import studio.engine.sampler.Sampler;
import studio.engine.sampler.SobolSampler;
import studio.engine.scene.Scene;

/**
 * Renders a scene into a {@link Film}: the image is cut into tiles, the tiles run on a
 * ForkJoinPool of the requested size, each finished tile is reported, and a cancel request stops
 * the render within a few milliseconds and a camera sample, inside a tile too. Each pixel's
 * samples are seeded from the pixel, so the result is the same, bit for bit, whatever the number
 * of threads.
 *
 * <p><b>Adaptive sampling</b> ({@link RenderSettings#adaptiveThreshold()} t &gt; 0). With N the
 * sampler's samples per pixel (the maximum), a pixel takes samples in batches of {@value #BATCH},
 * each a fresh pattern of the configured sampler (so each batch is stratified), drawn from the
 * pixel's random stream as it continues. After each full batch, with k the number of full batches
 * so far, n = {@value #BATCH} k the samples so far, and per channel c (linear light):
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
 * (floored at 1/255 in linear light, for near-black pixels). The square root sits between an absolute
 * limit (which lets dark pixels go noisy) and one relative to the mean (which spends most samples on
 * dark pixels that a few bright samples touch: on a pixel at mean 0.03 a relative limit wants about
 * six times the samples, for an error nobody sees in linear light). Measured on the speed-accuracy
 * bench, the square root reaches the same RMSE with 5-15% fewer samples than the relative limit on
 * every chart scene. The R_c term is there because with stratified batches and two or
 * three batches a pixel cut by an edge often has identical batch means (SE = 0) by chance; the mean
 * of n two-valued samples cannot be trusted to better than one sample's step. Otherwise the pixel
 * stops at N samples; if N is not a multiple of {@value #BATCH}, the last batch is a pattern of
 * N mod {@value #BATCH} samples. A pixel therefore takes at least min(N, {@value #MIN_BATCHES} x
 * {@value #BATCH}) samples: a flat pixel (all samples equal, or varying smoothly by much less than
 * the threshold) stops there; edges, shadow borders, highlights and reflections take more. The
 * pixel's value is the mean of all its samples. The rule uses only the pixel's own samples, so the
 * image is still the same at any thread count.
 *
 * <p>With the {@code sobol} sampler, adaptive sampling instead walks one scrambled Sobol sequence per
 * pixel, in two passes over each tile. First every pixel takes {@value #BASE} samples, and so does a
 * one-pixel ring around the tile (the ring's samples are the same its own tiles take, and are shared
 * with them through {@link TileBorders}). A pixel then
 * stops at {@value #BASE} if all 36 base samples of its 3 x 3 neighbourhood agree: per channel c,
 * (largest - smallest of them) / {@value #BASE} &lt;= L, with L as above from the pixel's own means. Looking at the neighbours finds the thin edges, shadow slivers and specks that the pixel's
 * own four samples miss but a neighbour's catch. Otherwise the pixel walks on along its sequence,
 * doubling: after n = 2^k samples the means A_c of the first and B_c of the second n/2 samples are
 * both estimates from a stratified (0, k-1, 2)-net, and the pixel stops when
 * <pre>
 *     for every c: max(|A_c - B_c| / 2, R_c) &lt;= L
 * </pre>
 * (R_c as above: two halves of a few stratified samples can agree by chance on an edge)
 * else at N. Independent batches would lose the stratification (their error falls like N^-1/2);
 * halves of one sequence keep it, so the estimate and the image both improve like a fixed-count
 * Sobol pattern. Every decision reads only samples seeded by pixel, so the image is the same at any
 * thread count.
 */
public final class Renderer {

    /** Adaptive sampling with sobol: the samples every pixel takes before it is judged. */
    public static final int BASE = 4;
    /** Fewer tiles than this per thread get smaller tiles (see {@link #tileSize}). */
    static final int TILES_PER_THREAD = 16;
    /** The largest tile with its one-pixel ring. */
    private static final int RING_TILE = RenderSettings.TILE_SIZE + 2;
    /** Adaptive sampling: samples per batch. */
    public static final int BATCH = 4;
    /** Adaptive sampling: a pixel takes at least this many batches (if the maximum allows). */
    public static final int MIN_BATCHES = 2;
    /** Adaptive sampling: the error limit scales with the root of the pixel's brightest channel, but of at least this. */
    public static final double ERROR_FLOOR = 1.0 / 255;
    /**
     * While tiles are rendered, the calling thread asks the cancel condition this often: a render
     * stops within this and one camera sample of its cancel or deadline.
     */
    static final long POLL_MILLIS = 5;

    private Renderer() {
    }

    public static RenderResult render(Scene scene, RenderSettings settings) {
        return render(scene, settings, RenderListener.NONE, () -> false);
    }

    /**
     * Renders the scene. {@code cancelled} is asked before each tile and, while tiles are being
     * rendered, every {@value #POLL_MILLIS} ms by the calling thread (never per sample: it may be
     * slow); once it answers true, every tile stops within one camera sample (see {@link StopSignal}).
     * The render returns or throws once no tile is being rendered any more (unless the calling
     * thread is interrupted: then at once, and the tiles stop within a sample).
     *
     * @throws RenderCancelledException if {@code cancelled} turned true before the last tile was done
     */
    public static RenderResult render(Scene scene, RenderSettings settings, RenderListener listener,
                                     BooleanSupplier cancelled) {
        return render(scene, settings, new Film(settings.width(), settings.height()), PixelLattice.ALL, null,
                listener, cancelled);
    }

    /**
     * Renders only the pixels of {@code pixels} that are not on {@code except} (null: none
     * excepted) into {@code film}, which has the settings' size; the film's other pixels are left
     * as they are. Each pixel comes out as in a whole render, so rendering nested lattices one
     * after the other (see {@link PixelLattice}) fills the film with the whole render's pixels.
     * Only for fixed sampling: adaptive sampling with sobol judges a pixel by its neighbours.
     * Cancelled as {@link #render(Scene, RenderSettings, RenderListener, BooleanSupplier)} is.
     *
     * @throws IllegalArgumentException if the settings are adaptive (and the lattice is not every
     *                                  pixel), or the film's size is not the settings'
     */
    public static RenderResult render(Scene scene, RenderSettings settings, Film film, PixelLattice pixels,
                                     PixelLattice except, RenderListener listener, BooleanSupplier cancelled) {
        if (film.width() != settings.width() || film.height() != settings.height()) {
            throw new IllegalArgumentException("the film is " + film.width() + "x" + film.height()
                    + ", the settings " + settings.width() + "x" + settings.height());
        }
        if (settings.adaptive() && (!pixels.equals(PixelLattice.ALL) || except != null)) {
            throw new IllegalArgumentException("adaptive sampling renders every pixel");
        }
        long start = System.nanoTime();
        int tileSize = tileSize(settings.width(), settings.height(), settings.effectiveThreads());
        List<TileRect> tiles = tiles(settings.width(), settings.height(), tileSize);
        // adaptive sampling with sobol is progressive (see TileWorker#progressiveTile)
        TileBorders borders = settings.adaptive() && settings.sampler() instanceof SobolSampler
                ? new TileBorders(settings.width(), settings.height(), tileSize) : null;
        StopSignal stop = new StopSignal();
        CountDownLatch ended = new CountDownLatch(tiles.size());
        AtomicReference<Throwable> failure = new AtomicReference<>();
        AtomicInteger done = new AtomicInteger();
        LongAdder rays = new LongAdder();
        LongAdder samples = new LongAdder();
        LongAdder nonFinite = new LongAdder();
        ThreadLocal<TileWorker> workers = ThreadLocal.withInitial(
                () -> new TileWorker(scene, settings, borders, stop));

        ForkJoinPool pool = new ForkJoinPool(settings.effectiveThreads());
        try {
            for (TileRect tile : tiles) {
                pool.execute(() -> {
                    try {
                        if (stop.raised() || cancelled.getAsBoolean()) {
                            stop.raise();
                            return;
                        }
                        TileWorker worker = workers.get();
                        long raysBefore = worker.integrator.rays, samplesBefore = worker.samples;
                        long bad = worker.render(film, tile, pixels, except);
                        rays.add(worker.integrator.rays - raysBefore);
                        samples.add(worker.samples - samplesBefore);
                        nonFinite.add(bad);
                        listener.tileFinished(film, tile, done.incrementAndGet(), tiles.size());
                    } catch (RenderCancelledException e) {
                        stop.raise();
                    } catch (RuntimeException | Error e) {
                        failure.compareAndSet(null, e);
                        stop.raise(); // the render has failed: the other tiles need not go on
                    } finally {
                        ended.countDown();
                    }
                });
            }
            while (!ended.await(POLL_MILLIS, TimeUnit.MILLISECONDS)) {
                if (!stop.raised() && cancelled.getAsBoolean()) {
                    stop.raise();
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new RenderCancelledException();
        } finally {
            stop.raise(); // a no-op unless the render ends early: interrupted, or the condition threw
            pool.shutdownNow();
        }
        Throwable failed = failure.get();
        if (failed instanceof RuntimeException runtime) {
            throw runtime;
        }
        if (failed instanceof Error error) {
            throw error;
        }
        if (done.get() < tiles.size()) {
            throw new RenderCancelledException();
        }
        return new RenderResult(film, rays.sum(), nonFinite.sum(), System.nanoTime() - start, samples.sum());
    }

    /**
     * {@link RenderSettings#TILE_SIZE}, or half of it when that would leave fewer than
     * {@value #TILES_PER_THREAD} tiles per thread: with few tiles, the one that holds most of the work
     * (the edges, under adaptive sampling) would finish alone while the other threads wait.
     */
    static int tileSize(int width, int height, int threads) {
        int size = RenderSettings.TILE_SIZE;
        long tiles = (long) ((width + size - 1) / size) * ((height + size - 1) / size);
        return tiles < (long) TILES_PER_THREAD * threads ? size / 2 : size;
    }

    /** The image cut into tiles of at most size x size, row by row from the top left. */
    static List<TileRect> tiles(int width, int height, int size) {
        List<TileRect> tiles = new ArrayList<>();
        for (int y = 0; y < height; y += size) {
            for (int x = 0; x < width; x += size) {
                tiles.add(new TileRect(x, y, Math.min(size, width - x), Math.min(size, height - y)));
            }
        }
        return tiles;
    }

    /** Per-thread state: the integrator, the random generator, the sample buffers and the batch statistics. */
    private static final class TileWorker {
        final Integrator integrator;
        final Camera camera;
        final Sampler sampler;
        /** Adaptive sampling: a full batch, and the last, partial batch when the maximum is not a multiple. */
        final Sampler batchSampler, remainderSampler;
        final SobolSampler.Sequence sequence = new SobolSampler.Sequence();
        /**
         * Adaptive sampling with sobol walks one Sobol sequence per pixel (see progressiveTile) and
         * shares the base samples of the tiles' edges here; null for every other render.
         */
        final TileBorders borders;
        /** Read before every camera sample. */
        final StopSignal stop;
        final Ray cameraRay = new Ray();
        /** Progressive adaptive sampling: each base pixel's sum and per-channel range, over a tile and its ring. */
        final double[] baseSum = new double[3 * RING_TILE * RING_TILE];
        final double[] baseMin = new double[3 * RING_TILE * RING_TILE], baseMax = new double[3 * RING_TILE * RING_TILE];
        final PixelRandom random = new PixelRandom();
        final double[] xs, ys;
        final int width, height;
        final double aspect;
        final long seed;
        final double threshold;
        /** Camera samples taken so far by this worker. */
        long samples;
        /** The radiance summed over the last call of {@link #trace}. */
        private double sumR, sumG, sumB;
        /** The smallest and largest finite sample values per channel since the last {@link #resetRange}. */
        private double minR, minG, minB, maxR, maxG, maxB;

        TileWorker(Scene scene, RenderSettings settings, TileBorders borders, StopSignal stop) {
            this.borders = borders;
            this.stop = stop;
            integrator = new Integrator(scene, settings.maxDepth(), settings.minPathWeight());
            camera = scene.camera();
            sampler = settings.sampler();
            int n = sampler.samplesPerPixel();
            threshold = settings.adaptiveThreshold();
            batchSampler = settings.adaptive() && n >= BATCH ? sampler.withSamplesPerPixel(BATCH) : null;
            remainderSampler = settings.adaptive() && n % BATCH != 0 ? sampler.withSamplesPerPixel(n % BATCH) : null;
            xs = new double[n];
            ys = new double[n];
            width = settings.width();
            height = settings.height();
            aspect = (double) width / height;
            seed = settings.seed();
        }

        /**
         * Renders the tile's pixels on {@code pixels} and not on {@code except} (null: none) into
         * the film; returns how many samples came out non-finite.
         */
        long render(Film film, TileRect tile, PixelLattice pixels, PixelLattice except) {
            if (borders != null) {
                return progressiveTile(film, tile);
            }
            long bad = 0;
            int step = pixels.step();
            for (int y = pixels.first(tile.y()); y < tile.y() + tile.height(); y += step) {
                for (int x = pixels.first(tile.x()); x < tile.x() + tile.width(); x += step) {
                    if (except != null && except.contains(x, y)) {
                        continue;
                    }
                    random.reset(x, y, seed);
                    bad += threshold <= 0 ? fixedPixel(film, x, y) : adaptivePixel(film, x, y);
                }
            }
            return bad;
        }

        /** All of the sampler's samples, from one pattern. */
        private long fixedPixel(Film film, int x, int y) {
            int n = sampler.samplesPerPixel();
            sampler.generate(random, xs, ys);
            long bad = trace(x, y, n);
            samples += n;
            film.set(x, y, sumR / n, sumG / n, sumB / n);
            return bad;
        }

        /**
         * Adaptive sampling along one Sobol sequence, in two passes over the tile. First every pixel of
         * the tile and of a one-pixel ring around it takes {@value #BASE} samples (a ring pixel's are
         * the same samples its own tile takes, so tiles need not wait for each other; whichever tile
         * takes an edge pixel's first leaves them in {@link TileBorders} for the other). Then each
         * pixel of the tile stops there if all base samples of its 3 x 3 neighbourhood agree, else it
         * walks on along its sequence, doubling, and after 2^k samples compares the estimate from the
         * first half with the one from the second half, each a stratified (0, k-1, 2)-net: half their
         * difference estimates the error of the whole.
         */
        private long progressiveTile(Film film, TileRect tile) {
            int max = sampler.samplesPerPixel();
            int x0 = Math.max(0, tile.x() - 1), y0 = Math.max(0, tile.y() - 1);
            int x1 = Math.min(width, tile.x() + tile.width() + 1), y1 = Math.min(height, tile.y() + tile.height() + 1);
            int stride = x1 - x0;
            int base = Math.min(max, BASE);
            long bad = 0;
            for (int y = y0; y < y1; y++) {
                for (int x = x0; x < x1; x++) {
                    int i = (y - y0) * stride + x - x0;
                    int entry = borders.entryOf(x, y);
                    long badHere = entry < 0 ? -1 : borders.loadOrClaim(entry, baseSum, baseMin, baseMax, 3 * i, stop);
                    if (badHere < 0) {
                        random.reset(x, y, seed);
                        sequence.seed(random);
                        sequence.fill(0, base, xs, ys);
                        resetRange();
                        try {
                            badHere = trace(x, y, 0, base);
                        } catch (RuntimeException | Error e) {
                            if (entry >= 0) {
                                borders.abandon(entry);
                            }
                            throw e;
                        }
                        baseSum[3 * i] = sumR;
                        baseSum[3 * i + 1] = sumG;
                        baseSum[3 * i + 2] = sumB;
                        baseMin[3 * i] = minR; baseMin[3 * i + 1] = minG; baseMin[3 * i + 2] = minB;
                        baseMax[3 * i] = maxR; baseMax[3 * i + 1] = maxG; baseMax[3 * i + 2] = maxB;
                        if (entry >= 0) {
                            borders.store(entry, baseSum, baseMin, baseMax, 3 * i, (int) badHere);
                        }
                    }
                    if (tile.contains(x, y)) {
                        bad += badHere;
                    }
                }
            }
            for (int y = tile.y(); y < tile.y() + tile.height(); y++) {
                for (int x = tile.x(); x < tile.x() + tile.width(); x++) {
                    int i = (y - y0) * stride + x - x0;
                    double r = baseSum[3 * i] / base, g = baseSum[3 * i + 1] / base, b = baseSum[3 * i + 2] / base;
                    double limit = limitOf(Math.max(r, Math.max(g, b)));
                    if (base >= max || neighbourhoodStep(i, stride, x - x0, y - y0, x1 - x0, y1 - y0, base) <= limit) {
                        samples += base;
                        film.set(x, y, r, g, b);
                    } else {
                        bad += refinePixel(film, x, y, i, base);
                    }
                }
            }
            return bad;
        }

        /**
         * The step one base sample makes in a mean, across pixel i's 3 x 3 neighbourhood: the range of
         * all their base samples in the channel where it is widest, over {@code base}.
         */
        private double neighbourhoodStep(int i, int stride, int cx, int cy, int w, int h, int base) {
            double loR = Double.POSITIVE_INFINITY, loG = loR, loB = loR;
            double hiR = Double.NEGATIVE_INFINITY, hiG = hiR, hiB = hiR;
            int nx0 = Math.max(0, cx - 1), nx1 = Math.min(w - 1, cx + 1);
            for (int ny = Math.max(0, cy - 1); ny <= Math.min(h - 1, cy + 1); ny++) {
                int row = i + (ny - cy) * stride - cx;
                for (int nx = nx0; nx <= nx1; nx++) {
                    int j = 3 * (row + nx);
                    loR = Math.min(loR, baseMin[j]);
                    loG = Math.min(loG, baseMin[j + 1]);
                    loB = Math.min(loB, baseMin[j + 2]);
                    hiR = Math.max(hiR, baseMax[j]);
                    hiG = Math.max(hiG, baseMax[j + 1]);
                    hiB = Math.max(hiB, baseMax[j + 2]);
                }
            }
            return Math.max(hiR - loR, Math.max(hiG - loG, hiB - loB)) / base;
        }

        /**
         * Walks on along pixel i's sequence from its {@code base} samples, doubling, until the halves
         * agree (see {@link Renderer}) or the maximum is reached.
         */
        private long refinePixel(Film film, int x, int y, int i, int base) {
            int max = sampler.samplesPerPixel();
            random.reset(x, y, seed);
            sequence.seed(random);
            minR = baseMin[3 * i]; minG = baseMin[3 * i + 1]; minB = baseMin[3 * i + 2];
            maxR = baseMax[3 * i]; maxG = baseMax[3 * i + 1]; maxB = baseMax[3 * i + 2];
            double totalR = baseSum[3 * i], totalG = baseSum[3 * i + 1], totalB = baseSum[3 * i + 2];
            long bad = 0;
            int taken = base;
            while (taken < max) {
                double firstR = totalR, firstG = totalG, firstB = totalB;
                int half = taken, target = Math.min(max, taken * 2);
                sequence.fill(taken, target - taken, xs, ys);
                bad += trace(x, y, taken, target - taken);
                totalR += sumR;
                totalG += sumG;
                totalB += sumB;
                taken = target;
                if (taken < max && half * 2 == taken) {
                    double dR = Math.abs(firstR - (totalR - firstR)) / half;
                    double dG = Math.abs(firstG - (totalG - firstG)) / half;
                    double dB = Math.abs(firstB - (totalB - firstB)) / half;
                    double mean = Math.max(totalR, Math.max(totalG, totalB)) / taken;
                    double limit = limitOf(mean);
                    double step = Math.max(maxR - minR, Math.max(maxG - minG, maxB - minB)) / taken;
                    if (Math.max(dR, Math.max(dG, dB)) / 2 <= limit && step <= limit) {
                        break;
                    }
                }
            }
            samples += taken;
            film.set(x, y, totalR / taken, totalG / taken, totalB / taken);
            return bad;
        }

        /** Batches of {@link #BATCH} samples until the pixel's estimate is good enough (see {@link Renderer}). */
        private long adaptivePixel(Film film, int x, int y) {
            int max = sampler.samplesPerPixel();
            long bad = 0;
            int taken = 0, batches = 0;
            double totalR = 0, totalG = 0, totalB = 0;
            // Welford's running mean and sum of squared deviations of the full batches' means, per channel.
            double meanR = 0, meanG = 0, meanB = 0, m2R = 0, m2G = 0, m2B = 0;
            resetRange();
            while (taken < max) {
                int size = Math.min(BATCH, max - taken);
                (size == BATCH ? batchSampler : remainderSampler).generate(random, xs, ys);
                bad += trace(x, y, size);
                taken += size;
                totalR += sumR;
                totalG += sumG;
                totalB += sumB;
                if (size < BATCH) {
                    break; // the partial batch is the last one
                }
                batches++;
                double r = sumR / BATCH, g = sumG / BATCH, b = sumB / BATCH;
                double dR = r - meanR, dG = g - meanG, dB = b - meanB;
                meanR += dR / batches;
                meanG += dG / batches;
                meanB += dB / batches;
                m2R += dR * (r - meanR);
                m2G += dG * (g - meanG);
                m2B += dB * (b - meanB);
                if (batches >= MIN_BATCHES) {
                    double limit = limitOf(Math.max(meanR, Math.max(meanG, meanB)));
                    double step = Math.max(maxR - minR, Math.max(maxG - minG, maxB - minB)) / taken;
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

        /** The error a pixel whose brightest channel's mean is {@code brightest} may keep: see {@link Renderer}. */
        private double limitOf(double brightest) {
            return threshold * Math.sqrt(Math.max(brightest, ERROR_FLOOR));
        }

        private void resetRange() {
            minR = minG = minB = Double.POSITIVE_INFINITY;
            maxR = maxG = maxB = Double.NEGATIVE_INFINITY;
        }

        /** Traces samples 0 .. count-1 of the buffers; their sum goes to sumR, sumG, sumB. Widens the range. */
        private long trace(int x, int y, int count) {
            return trace(x, y, 0, count);
        }

        /**
         * Traces samples first .. first + count - 1 of the pattern in xs, ys; sums into sumR/G/B.
         *
         * @throws RenderCancelledException once the render's stop signal is raised
         */
        private long trace(int x, int y, int first, int count) {
            long bad = 0;
            double r = 0, g = 0, b = 0;
            for (int s = first; s < first + count; s++) {
                stop.check();
                double ndcX = 2 * (x + xs[s]) / width - 1;
                double ndcY = 1 - 2 * (y + ys[s]) / height;
                Ray ray = camera.ray(ndcX, ndcY, aspect, cameraRay);
                // Each sample starts with throughput 1: culling by the sample's share of the pixel
                // (1/N) would drop every weak reflection at high sample counts, a bias, not noise.
                integrator.trace(ray, 0, 1.0);
                double cr = integrator.r(), cg = integrator.g(), cb = integrator.b();
                if (Double.isFinite(cr) && Double.isFinite(cg) && Double.isFinite(cb)) {
                    r += cr;
                    g += cg;
                    b += cb;
                    minR = Math.min(minR, cr);
                    minG = Math.min(minG, cg);
                    minB = Math.min(minB, cb);
                    maxR = Math.max(maxR, cr);
                    maxG = Math.max(maxG, cg);
                    maxB = Math.max(maxB, cb);
                } else {
                    bad++;
                }
            }
            sumR = r;
            sumG = g;
            sumB = b;
            return bad;
        }
    }
}

package studio.engine.render;

import studio.engine.camera.Camera;
import studio.engine.geometry.Frustum;
import studio.engine.geometry.Ray;
import studio.engine.sampler.LightPoints;
import studio.engine.scene.Scene;

/**
 * Traces a pixel's camera samples, one worker's: a pattern's samples in, their sum and each
 * channel's smallest and largest finite value out. Non-finite samples are dropped and counted.
 * Every sampling strategy traces through one of these; it reads the render's stop signal before
 * every sample. In a scene with sphere or area lights each sample also takes a 2D point for its
 * light samples from the pattern ({@link LightPoints}).
 */
final class SampleTracer {

    /**
     * A call tracing at least this many samples first lists the objects their rays can meet
     * ({@link PixelCandidates}); fewer would not repay the search.
     */
    static final int CANDIDATES_FROM = 4;
    /**
     * Pixels of a row listed together: one pyramid over runs of this many pixels (from a column
     * that is a multiple of it), its lists kept while the pixels traced stay in the run. A run's
     * lists hold those of each of its pixels, so the pixels are the same to the bit; the rays test
     * a few more objects each, and the pyramids' searches, which took a third of the 10,000 spheres'
     * render, happen a quarter as often. Warm, 800x600, 16 jittered samples, 2 threads, medians of
     * the last 8 of 16 renders in one JVM: one pixel 437 ms, runs of 2 379, of 4 327, of 8 344.
     */
    static final int LIST_RUN = 4;
    /**
     * A sample's texture footprint: this share of its cell of the pixel (the pixel over the square
     * root of its samples). The sampler's stratification already averages across cells; the
     * texture's filter need only remove what lies below a cell. The checker horizon (TEX-01,
     * docs/robustness.md; 480x240, 16 sobol samples, RMSE in 8-bit levels against 1,024): a whole
     * cell 3.56, a half 2.27, a quarter 2.36.
     */
    static final double FOOTPRINT_SHARE = 0.5;

    private final Integrator integrator;
    /** The light points of a run's samples, or null where every light is a point (which needs none). */
    private final LightPoints lightPoints;
    private final Camera camera;
    private final StopSignal stop;
    private final Ray cameraRay = new Ray();
    private final Frustum frustum = new Frustum();
    /** Whether pixels list what their rays can meet ({@link PixelCandidates#pay}). */
    private boolean useCandidates;
    private final int width, height;
    /** The row and first column of the run of pixels whose lists {@link PixelCandidates} holds (row -1: none). */
    private int listedRow = -1, listedFrom;
    private final double aspect;
    /** The radiance summed over the last call of {@link #trace}. */
    double sumR, sumG, sumB;
    /** The smallest and largest finite sample values per channel since the last {@link #resetRange}. */
    double minR, minG, minB, maxR, maxG, maxB;

    SampleTracer(Scene scene, RenderSettings settings, StopSignal stop) {
        this.stop = stop;
        useCandidates = PixelCandidates.pay(scene);
        integrator = new Integrator(scene, settings.maxDepth(), settings.minPathWeight(),
                new BranchRoulette(BranchRoulette.BELOW, settings.seed()));
        camera = scene.camera();
        lightPoints = scene.lights().stream().anyMatch(l -> l.soft())
                ? new LightPoints(settings.sampler(), settings.seed()) : null;
        integrator.coneSpread = camera.pixelSpread(settings.height())
                / Math.sqrt(settings.sampler().samplesPerPixel()) * FOOTPRINT_SHARE;
        width = settings.width();
        height = settings.height();
        aspect = (double) width / height;
    }

    /** A pyramid holding every camera ray through pixels from .. from + LIST_RUN - 1 of row y (those inside the image). */
    private Frustum cameraRays(int from, int y) {
        int to = Math.min(width, from + LIST_RUN);
        return camera.frustum(ndcX(from, 0), ndcX(to, 0), ndcY(y, 1), ndcY(y, 0), aspect, frustum);
    }

    /** Normalised device x of a sample at offset dx in column x: -1 at the left edge, 1 at the right. */
    private double ndcX(int x, double dx) {
        return 2 * (x + dx) / width - 1;
    }

    /** Normalised device y of a sample at offset dy in row y: 1 at the top edge, -1 at the bottom. */
    private double ndcY(int y, double dy) {
        return 1 - 2 * (y + dy) / height;
    }

    /** From now on every ray searches the whole scene (tests compare the two ways). */
    SampleTracer withoutCandidates() {
        useCandidates = false;
        return this;
    }

    /** Whether the last {@link #trace} listed the objects its camera rays can hit. */
    boolean listedCandidates() {
        return integrator.candidates.cameraCount >= 0;
    }

    /** Records the rays of the next samples as pixel p's in {@code paths} (null: nowhere). */
    void recordInto(PixelPaths paths, int p) {
        integrator.paths = paths;
        integrator.pathPixel = p;
    }

    /** Rays traced so far. */
    long rays() {
        return integrator.rays;
    }

    void resetRange() {
        minR = minG = minB = Double.POSITIVE_INFINITY;
        maxR = maxG = maxB = Double.NEGATIVE_INFINITY;
    }

    /** The widest channel's range of the samples since {@link #resetRange}. */
    double widestRange() {
        return Math.max(maxR - minR, Math.max(maxG - minG, maxB - minB));
    }

    /**
     * Traces samples first .. first + count - 1 of the pattern in xs, ys (offsets within pixel
     * (x, y)); sums them into sumR/G/B and widens the range.
     *
     * @return how many came out non-finite
     * @throws RenderCancelledException once the render's stop signal is raised
     */
    long trace(int x, int y, double[] xs, double[] ys, int first, int count) {
        long bad = 0;
        if (count >= CANDIDATES_FROM && useCandidates) {
            if (y != listedRow || x < listedFrom || x >= listedFrom + LIST_RUN) {
                listedRow = y;
                listedFrom = x - x % LIST_RUN;
                integrator.candidates.forCameraRaysIn(cameraRays(listedFrom, y));
            }
        } else {
            integrator.candidates.none();
            listedRow = -1;
        }
        if (lightPoints != null) {
            lightPoints.start(x, y, first, count, xs, ys);
        }
        double r = 0, g = 0, b = 0;
        for (int s = first; s < first + count; s++) {
            stop.check();
            if (lightPoints != null) {
                integrator.lightU = lightPoints.u(s);
                integrator.lightV = lightPoints.v(s);
            }
            Ray ray = camera.ray(ndcX(x, xs[s]), ndcY(y, ys[s]), aspect, cameraRay);
            // Each sample starts with throughput 1: culling by the sample's share of the pixel
            // (1/N) would drop every weak reflection at high sample counts, a bias, not noise.
            integrator.roulette.startSample(x, y, s);
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

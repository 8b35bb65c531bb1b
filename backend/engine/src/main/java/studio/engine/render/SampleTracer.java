package studio.engine.render;

import studio.engine.camera.Camera;
import studio.engine.geometry.Ray;
import studio.engine.geometry.RayBundle;
import studio.engine.math.Vec3;
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
     * A call tracing at least this many samples sends its camera rays as a {@link RayBundle}, for
     * the scene to list what they can meet once; fewer would not repay the listing, unless the
     * caller traces a row's pixels one after the other (progressive sobol's base pass, see
     * {@link #trace(int, int, double[], double[], int, int, boolean)}).
     */
    static final int BUNDLE_FROM = 4;
    /**
     * Pixels of a row bundled together: one pyramid over runs of this many pixels (from a column
     * that is a multiple of it), kept while the pixels traced stay in the run. The rays test a few
     * more objects each, and the listings, which took a third of 10,000 spheres' render pixel by
     * pixel, happen a quarter as often: runs of 4 render it fastest of 1, 2, 4 and 8 (warm).
     */
    static final int RUN = 4;
    /**
     * A sample's texture footprint: this share of its cell of the pixel (the pixel over the square
     * root of its samples). The sampler's stratification already averages across cells; the
     * texture's filter need only remove what lies below a cell. A half gives the checker horizon's
     * least error of a whole, a half and a quarter cell (TEX-01; {@code CheckerHorizonTest} prints it).
     */
    static final double FOOTPRINT_SHARE = 0.5;

    private final Integrator integrator;
    /** The light points of a run's samples, or null where every light is a point (which needs none). */
    private final LightPoints lightPoints;
    private final Camera camera;
    private final StopSignal stop;
    private final Ray cameraRay = new Ray();
    /** The camera rays' bundle, and the row and first column of the run of pixels it holds (row -1: none). */
    private final RayBundle bundle = new RayBundle();
    private int bundledRow = -1, bundledFrom;
    private final int width, height;
    private final double aspect;
    /** The radiance summed over the last call of {@link #trace}. */
    double sumR, sumG, sumB;
    /** The smallest and largest finite sample values per channel since the last {@link #resetRange}. */
    double minR, minG, minB, maxR, maxG, maxB;

    SampleTracer(Scene scene, RenderSettings settings, StopSignal stop) {
        this.stop = stop;
        integrator = new Integrator(scene, settings.maxDepth(), settings.minPathWeight(),
                new BranchRoulette(BranchRoulette.BELOW, settings.seed()));
        integrator.wholeLights = settings.adaptive();
        camera = scene.camera();
        lightPoints = scene.lights().stream().anyMatch(l -> l.soft())
                ? new LightPoints(settings.sampler(), settings.seed()) : null;
        integrator.coneSpread = camera.pixelSpread(settings.height())
                / Math.sqrt(settings.sampler().samplesPerPixel()) * FOOTPRINT_SHARE;
        width = settings.width();
        height = settings.height();
        aspect = (double) width / height;
    }

    /** Normalised device x of a sample at offset dx in column x: -1 at the left edge, 1 at the right. */
    private double ndcX(int x, double dx) {
        return 2 * (x + dx) / width - 1;
    }

    /** Normalised device y of a sample at offset dy in row y: 1 at the top edge, -1 at the bottom. */
    private double ndcY(int y, double dy) {
        return 1 - 2 * (y + dy) / height;
    }

    /** Whether the scene has a sphere or area light, whose samples each take a point on it. */
    boolean softLights() {
        return lightPoints != null;
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

    /**
     * Whether the next calls' samples ask, of each shadow ray to a sphere or area light that something
     * stopped, whether the point sees part of the light ({@link #penumbraLight}).
     */
    void watchPenumbrae(boolean watch) {
        integrator.watchPenumbrae = watch;
    }

    /**
     * The most a sphere or area light could have added, unshadowed, to one of the last call's
     * samples whose shadow ray to it went dark where the point may see part of the light (0 if none,
     * or unless {@link #watchPenumbrae}): the sample's point lies in a penumbra.
     */
    double penumbraLight() {
        return integrator.penumbraLight;
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
        // a call of fewer samples traces without the bundle but keeps it: the pyramid of its run
        // holds the run's next calls' rays too (a refined pixel's first calls are short)
        return trace(x, y, xs, ys, first, count, count >= BUNDLE_FROM);
    }

    /**
     * {@link #trace(int, int, double[], double[], int, int)}, the camera rays bundled or not as the
     * caller says. A caller that traces the pixels of a row one after the other, a few samples each,
     * bundles every call: one pyramid's listing then serves the next pixels of its run of {@value #RUN}
     * too (the same hits either way).
     */
    long trace(int x, int y, double[] xs, double[] ys, int first, int count, boolean bundled) {
        long bad = 0;
        if (bundled && (y != bundledRow || x < bundledFrom || x >= bundledFrom + RUN)) {
            bundledRow = y;
            bundledFrom = x - x % RUN;
            int to = Math.min(width, bundledFrom + RUN);
            Vec3 eye = camera.position();
            camera.frustum(ndcX(bundledFrom, 0), ndcX(to, 0), ndcY(y, 1), ndcY(y, 0), aspect,
                    bundle.aim(eye.x(), eye.y(), eye.z()));
        }
        if (lightPoints != null) {
            lightPoints.start(x, y, first, count, xs, ys);
        }
        double r = 0, g = 0, b = 0;
        integrator.penumbraLight = 0;
        integrator.startRun();
        for (int s = first; s < first + count; s++) {
            stop.check();
            if (lightPoints != null) {
                integrator.lightU = lightPoints.u(s);
                integrator.lightV = lightPoints.v(s);
            }
            Ray ray = camera.ray(ndcX(x, xs[s]), ndcY(y, ys[s]), aspect, cameraRay);
            ray.bundle = bundled ? bundle : null;
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

package studio.bench.kernel;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;

import studio.engine.camera.Camera;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Rays;
import studio.engine.math.Vec3;
import studio.engine.scene.Scene;

/**
 * The kernel's workload on one band of image rows, one worker's: for every pixel one camera ray
 * through the pixel centre ({@link Scene#intersect}, closest hit) and, where it hits, one shadow
 * ray to the scene's first light ({@link Scene#occluded}), spawned as the Integrator spawns its
 * shadow rays ({@link Rays#spawnTowards}, blocked only before {@value #SHADOW_END} of the light's
 * distance). No shading. The pixel-to-ray mapping is SampleTracer's with the sample at (0.5, 0.5).
 * Each pixel's outcome goes into a shared mask (workers write disjoint rows), so the pixels can be
 * compared with Embree's one by one. Owns its rays and hit record, so tracing allocates nothing.
 */
final class PrimaryShadowRays {

    /** As the Integrator's: a shadow ray is blocked only by hits closer than this fraction of the light's distance. */
    static final double SHADOW_END = 1 - 1e-9;
    /** A pixel's value in the mask: its camera ray missed, hit a lit point, or hit a point in shadow (PGM grey levels). */
    static final byte MISS = 0, LIT = (byte) 255, SHADOWED = (byte) 128;

    private final Scene scene;
    private final Camera camera;
    private final int width, height;
    private final double aspect;
    private final double lx, ly, lz;
    private final Ray primary = new Ray(), shadow = new Ray();
    private final Hit hit = new Hit();
    private final byte[] mask;
    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

    /** Counted by the last {@link #trace}. */
    long hits, occluded;
    /** The CPU time of the thread that ran the last {@link #trace}, in nanoseconds. */
    long cpuNanos;

    /** @param mask a byte a pixel, row by row, for the outcomes ({@link #MISS}, {@link #LIT}, {@link #SHADOWED}) */
    PrimaryShadowRays(Scene scene, int width, int height, byte[] mask) {
        this.scene = scene;
        this.mask = mask;
        this.camera = scene.camera();
        this.width = width;
        this.height = height;
        this.aspect = (double) width / height;
        Vec3 light = scene.lights().get(0).position();
        lx = light.x();
        ly = light.y();
        lz = light.z();
    }

    /** Traces rows {@code firstRow} to {@code endRow - 1}; sets {@link #hits}, {@link #occluded} and {@link #cpuNanos}. */
    void trace(int firstRow, int endRow) {
        long cpuStart = THREADS.getCurrentThreadCpuTime();
        long hitCount = 0, occludedCount = 0;
        for (int y = firstRow; y < endRow; y++) {
            double ndcY = 1 - 2 * (y + 0.5) / height;
            for (int x = 0; x < width; x++) {
                double ndcX = 2 * (x + 0.5) / width - 1;
                Ray ray = camera.ray(ndcX, ndcY, aspect, primary);
                if (!scene.intersect(ray, Double.POSITIVE_INFINITY, hit)) {
                    mask[y * width + x] = MISS;
                    continue;
                }
                hitCount++;
                Ray toLight = Rays.spawnTowards(hit, lx, ly, lz, shadow);
                double dx = lx - toLight.ox, dy = ly - toLight.oy, dz = lz - toLight.oz;
                if (scene.occluded(toLight, Math.sqrt(dx * dx + dy * dy + dz * dz) * SHADOW_END)) {
                    occludedCount++;
                    mask[y * width + x] = SHADOWED;
                } else {
                    mask[y * width + x] = LIT;
                }
            }
        }
        hits = hitCount;
        occluded = occludedCount;
        cpuNanos = THREADS.getCurrentThreadCpuTime() - cpuStart;
    }
}

package studio.bench.jmh;

import java.util.SplittableRandom;

import studio.engine.accel.Aabb;
import studio.engine.geometry.Ray;

/**
 * Pre-generated rays for the micro-benchmarks, so that a benchmark's loop only picks the next one
 * ({@code rays[i++ & MASK]}) and allocates nothing. Each ray starts on a sphere around a box and
 * ends at a random point inside it: {@code d = target - origin}, so t = 1 is the target (a shadow
 * ray's segment). Rays aimed at a box around a shape hit it in part and miss it in part, and come
 * from every direction: incoherent, unlike a camera's.
 */
public final class RandomRays {

    /** A power of two: enough rays that the branch predictor cannot learn the sequence. */
    public static final int COUNT = 1 << 14, MASK = COUNT - 1;

    private RandomRays() {
    }

    /** COUNT rays from a sphere of twice the box's half-diagonal around its centre to points inside the box. */
    public static Ray[] toward(Aabb box, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        double cx = (box.minX() + box.maxX()) / 2, cy = (box.minY() + box.maxY()) / 2, cz = (box.minZ() + box.maxZ()) / 2;
        double hx = (box.maxX() - box.minX()) / 2, hy = (box.maxY() - box.minY()) / 2, hz = (box.maxZ() - box.minZ()) / 2;
        double radius = 2 * Math.sqrt(hx * hx + hy * hy + hz * hz);
        Ray[] rays = new Ray[COUNT];
        for (int i = 0; i < COUNT; i++) {
            // a uniform direction: z uniform in [-1, 1], angle uniform
            double z = 2 * random.nextDouble() - 1, phi = 2 * Math.PI * random.nextDouble();
            double s = Math.sqrt(1 - z * z);
            double ox = cx + radius * s * Math.cos(phi), oy = cy + radius * s * Math.sin(phi), oz = cz + radius * z;
            double tx = cx + hx * (2 * random.nextDouble() - 1), ty = cy + hy * (2 * random.nextDouble() - 1),
                    tz = cz + hz * (2 * random.nextDouble() - 1);
            rays[i] = new Ray(ox, oy, oz, tx - ox, ty - oy, tz - oz);
        }
        return rays;
    }
}

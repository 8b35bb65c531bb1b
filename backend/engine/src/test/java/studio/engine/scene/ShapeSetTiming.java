package studio.engine.scene;

import java.util.Random;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Shape;
import studio.engine.geometry.Sphere;
import studio.engine.math.Vec3;

/**
 * Not a test: times the linear loop against the BVH for scenes of n objects like the editor's
 * (a floor plane, spheres and rotated boxes on it, seen by a camera), to place
 * {@link ShapeSet#LINEAR_MAX}. Run: {@code java -cp target/classes:target/test-classes
 * studio.engine.scene.ShapeSetTiming}. Prints nanoseconds per primary ray plus shadow ray.
 */
public final class ShapeSetTiming {

    private ShapeSetTiming() {
    }

    public static void main(String[] args) {
        int[] counts = {2, 3, 4, 5, 6, 7, 8, 10, 12, 16, 24, 32, 64};
        // Default: the whole [-5,5]^2 floor in view. "close": a narrow view where the objects fill the frame,
        // the BVH's worst case (its box tests cull little).
        boolean close = args.length > 0 && args[0].equals("close");
        Camera camera = close ? new Camera(new Vec3(0, 3, 6), new Vec3(0, 0.5, 0), new Vec3(0, 1, 0), 20)
                : new Camera(new Vec3(0, 4, 12), new Vec3(0, 0.5, 0), new Vec3(0, 1, 0), 50);
        Random random = new Random(1);
        Ray[] rays = new Ray[4096];
        for (int i = 0; i < rays.length; i++) {
            rays[i] = camera.ray(random.nextDouble() * 2 - 1, random.nextDouble() * 2 - 1, 4.0 / 3);
        }
        for (int n : counts) { // warm-up: every configuration compiled before any is timed
            Shape[] shapes = scene(n, new Random(n));
            time(ShapeSets.linear(shapes), rays);
            time(ShapeSets.bvh(shapes), rays);
        }
        System.out.println("objects  linear ns/ray  bvh ns/ray   (best of 7, alternating)");
        for (int n : counts) {
            Shape[] shapes = scene(n, new Random(n));
            ShapeSet linear = ShapeSets.linear(shapes), bvh = ShapeSets.bvh(shapes);
            double bestLinear = Double.POSITIVE_INFINITY, bestBvh = Double.POSITIVE_INFINITY;
            for (int rep = 0; rep < 7; rep++) {
                bestLinear = Math.min(bestLinear, time(linear, rays));
                bestBvh = Math.min(bestBvh, time(bvh, rays));
            }
            System.out.printf("%7d  %13.1f  %10.1f%n", n, bestLinear, bestBvh);
        }
    }

    /** A plane y=0 and n-1 spheres and boxes scattered over [-5,5]^2 on it (over [-1,1]^2 for a few). */
    static Shape[] scene(int n, Random random) {
        Shape[] shapes = new Shape[n];
        shapes[0] = new Plane(Vec3.ZERO, new Vec3(0, 1, 0));
        double spread = n <= 5 ? 2 : 10;
        for (int i = 1; i < n; i++) {
            double x = (random.nextDouble() - 0.5) * spread, z = (random.nextDouble() - 0.5) * spread;
            double s = 0.3 + random.nextDouble() * 0.5;
            shapes[i] = i % 2 == 0 ? new Sphere(new Vec3(x, s, z), s)
                    : new Box(new Vec3(x, s, z), new Vec3(s, 2 * s, s), new Vec3(0, random.nextDouble() * 90, 0));
        }
        return shapes;
    }

    private static double time(ShapeSet set, Ray[] rays) {
        Hit hit = new Hit();
        long sink = 0;
        int rounds = 40;
        long start = System.nanoTime();
        for (int r = 0; r < rounds; r++) {
            for (Ray ray : rays) {
                if (set.intersect(ray, Double.POSITIVE_INFINITY, hit)) {
                    sink += hit.primitive;
                    Ray shadow = new Ray(hit.px, hit.py + 1e-9, hit.pz, 0.3, 1, 0.2);
                    sink += set.occluded(shadow, Double.POSITIVE_INFINITY) ? 1 : 0;
                }
            }
        }
        long nanos = System.nanoTime() - start;
        if (sink == 42) {
            System.out.print("");
        }
        return (double) nanos / (rounds * rays.length);
    }
}

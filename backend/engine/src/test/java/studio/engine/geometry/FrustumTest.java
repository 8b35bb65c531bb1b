package studio.engine.geometry;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.math.Vec3;

/**
 * A pyramid keeps every box its rays meet, down to a box that is a single point on a ray, for
 * cameras far from the origin and pixels a few millionths of the image wide; and it drops what
 * lies clearly outside, so a scene's candidate lists stay short.
 */
class FrustumTest {

    private static double uniform(Random random, double lo, double hi) {
        return lo + (hi - lo) * random.nextDouble();
    }

    private static Vec3 randomPoint(Random random, double extent) {
        return new Vec3(uniform(random, -extent, extent), uniform(random, -extent, extent),
                uniform(random, -extent, extent));
    }

    /** A box that is the single point p. */
    private static double[] pointBox(double x, double y, double z) {
        return new double[] {x, y, z, x, y, z};
    }

    /** mayMeet with the slack for this box's own magnitude, as a scene gives its largest. */
    private static boolean meets(Frustum frustum, double[] box) {
        double magnitude = 0;
        for (double v : box) {
            magnitude = Math.max(magnitude, Math.abs(v));
        }
        return frustum.within(magnitude).mayMeet(box, 0);
    }

    private static Camera randomCamera(Random random) {
        double far = Math.pow(10, uniform(random, 0, 6));
        Vec3 position = randomPoint(random, far);
        Vec3 target = position.plus(randomPoint(random, 1).plus(new Vec3(0, 0, 1e-3)));
        return new Camera(position, target, new Vec3(0, 1, 0), uniform(random, 5, 170));
    }

    /** A pixel, a square of normalised device coordinates from (x0, y0) and size across, of a camera. */
    private record Pixel(Camera camera, double aspect, double x0, double y0, double size) {

        /** A random camera's pixel, of an image up to 40,000 wide (5e-5 across), and its pyramid into frustum. */
        static Pixel random(Random random, double minAspect, double maxAspect, Frustum frustum) {
            Camera camera = randomCamera(random);
            double aspect = uniform(random, minAspect, maxAspect);
            double size = Math.pow(10, uniform(random, -4.3, -0.5));
            double x0 = uniform(random, -1, 1 - size), y0 = uniform(random, -1, 1 - size);
            camera.frustum(x0, x0 + size, y0, y0 + size, aspect, frustum);
            return new Pixel(camera, aspect, x0, y0, size);
        }

        /** Into out: the ray through the pixel's corner s (0 to 3), or for s of 4 on through a random point in it. */
        Ray ray(int s, Random random, Ray out) {
            double x = s < 4 ? x0 + (s & 1) * size : x0 + size * random.nextDouble();
            double y = s < 4 ? y0 + (s >> 1) * size : y0 + size * random.nextDouble();
            return camera.ray(x, y, aspect, out);
        }
    }

    @Test
    void cameraRaysThroughTheRectangleMeetOnlyKeptBoxes() {
        Random random = new Random(3);
        Frustum frustum = new Frustum();
        Ray ray = new Ray();
        int dropped = 0;
        for (int pixel = 0; pixel < 2000; pixel++) {
            Pixel p = Pixel.random(random, 0.2, 5, frustum);
            Camera camera = p.camera();
            double aspect = p.aspect(), x0 = p.x0(), y0 = p.y0(), size = p.size();
            Vec3 o = camera.position();
            for (int s = 0; s < 20; s++) {
                p.ray(s, random, ray);
                double t = Math.pow(10, uniform(random, -6, 7));
                double px = ray.ox + t * ray.dx, py = ray.oy + t * ray.dy, pz = ray.oz + t * ray.dz;
                assertTrue(meets(frustum, pointBox(px, py, pz)), "a point on a ray of the pixel, t " + t);
                double e = 1e-3 * t;
                assertTrue(meets(frustum, new double[] {px - e, py - e, pz - e, px + e, py + e, pz + e}));
            }
            // a point as far outside the rectangle as the rectangle is wide, in front: dropped
            double ox = random.nextBoolean() ? x0 - size : x0 + 2 * size;
            camera.ray(ox, y0 + size / 2, aspect, ray);
            double t = uniform(random, 1, 100);
            if (!meets(frustum, pointBox(ray.ox + t * ray.dx, ray.oy + t * ray.dy, ray.oz + t * ray.dz))) {
                dropped++;
            }
            // behind the camera, on a ray of the pixel turned around: dropped
            camera.ray(x0 + size / 2, y0 + size / 2, aspect, ray);
            assertFalse(meets(frustum, pointBox(o.x() - t * ray.dx, o.y() - t * ray.dy, o.z() - t * ray.dz)));
        }
        assertTrue(dropped == 2000, "points a pixel's width outside dropped: " + dropped);
    }

    @Test
    void dropsNothingUntilToldTheBoxesMagnitude() {
        Camera camera = new Camera(new Vec3(0, 0, 5), Vec3.ZERO, new Vec3(0, 1, 0), 40);
        Frustum frustum = camera.frustum(-0.01, 0.01, -0.01, 0.01, 1, new Frustum());
        double[] aside = pointBox(3, 0, 0);

        assertTrue(frustum.mayMeet(aside, 0));
        assertFalse(frustum.within(3).mayMeet(aside, 0));
    }

}

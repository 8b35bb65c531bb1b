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
    void shadowPyramidHoldsEverySegmentFromThePointToTheBox() {
        Random random = new Random(5);
        Frustum frustum = new Frustum();
        int made = 0, droppedBeyond = 0, droppedBeside = 0;
        for (int i = 0; i < 3000; i++) {
            double scale = Math.pow(10, uniform(random, -2, 5));
            Vec3 c = randomPoint(random, scale);
            double hx = scale * Math.pow(10, uniform(random, -6, -1)), hy = hx * uniform(random, 0, 3);
            double hz = hx * uniform(random, 0, 3);
            double[] box = {c.x() - hx, c.y() - hy, c.z() - hz, c.x() + hx, c.y() + hy, c.z() + hz};
            Vec3 light = c.plus(randomPoint(random, 1).normalized().times(scale * uniform(random, 0.01, 10)));
            if (!frustum.overBox(light.x(), light.y(), light.z(), box)) {
                continue;
            }
            made++;
            for (int s = 0; s < 20; s++) {
                // a point of the box (corners included), then a point on its segment to the light
                double bx = s < 8 ? box[(s & 1) * 3] : uniform(random, box[0], box[3]);
                double by = s < 8 ? box[1 + ((s >> 1) & 1) * 3] : uniform(random, box[1], box[4]);
                double bz = s < 8 ? box[2 + ((s >> 2) & 1) * 3] : uniform(random, box[2], box[5]);
                double f = s % 3 == 0 ? 1 : random.nextDouble();
                double px = light.x() + f * (bx - light.x()), py = light.y() + f * (by - light.y());
                double pz = light.z() + f * (bz - light.z());
                assertTrue(meets(frustum, pointBox(px, py, pz)), "a point between the light and the box");
            }
            // twice as far from the light as the box's far side: dropped by the pyramid's end
            double d = Math.sqrt(Math.pow(c.x() - light.x(), 2) + Math.pow(c.y() - light.y(), 2)
                    + Math.pow(c.z() - light.z(), 2));
            double reach = 2 * (d + 2 * (hx + hy + hz)) / d;
            if (!meets(frustum, pointBox(light.x() + reach * (c.x() - light.x()), light.y() + reach * (c.y() - light.y()),
                    light.z() + reach * (c.z() - light.z())))) {
                droppedBeyond++;
            }
            // beside the box, as far out as the box is wide: dropped by a side
            if (!meets(frustum, pointBox(c.x() + 3 * hx + 3 * (hy + hz), c.y() + 3 * (hx + hy + hz), c.z()))
                    || !meets(frustum, pointBox(c.x() - 3 * (hx + hy + hz), c.y(), c.z() - 3 * (hx + hy + hz)))) {
                droppedBeside++;
            }
        }
        assertTrue(made > 2500, "pyramids made: " + made);
        assertTrue(droppedBeyond == made, "points beyond the box dropped: " + droppedBeyond + " of " + made);
        assertTrue(droppedBeside > made * 9 / 10, "points beside the box dropped: " + droppedBeside + " of " + made);
    }

    @Test
    void noPyramidFromInsideOrBesideTheBox() {
        Frustum frustum = new Frustum();
        double[] box = {0, 0, 0, 1, 1, 1};

        assertFalse(frustum.overBox(0.5, 0.5, 0.5, box), "inside");
        assertFalse(frustum.overBox(1, 0.5, 0.5, box), "on a face");
        assertFalse(frustum.overBox(1 + 1e-9, 0.5, 0.5, box), "just outside a face: wider than a half-space");
        assertTrue(frustum.overBox(5, 0.5, 0.5, box));
    }

    @Test
    void aPlanesPartInsideACameraPyramidHoldsEveryHitOnIt() {
        Random random = new Random(8);
        Frustum frustum = new Frustum();
        Ray ray = new Ray();
        Hit hit = new Hit();
        int bounded = 0, hits = 0;
        for (int pixel = 0; pixel < 3000; pixel++) {
            Pixel p = Pixel.random(random, 0.5, 2, frustum);
            Camera camera = p.camera();
            double scale = Math.abs(camera.position().x()) + Math.abs(camera.position().y()) + 1;
            Plane plane = new Plane(camera.position().plus(randomPoint(random, scale)), randomPoint(random, 1));
            double[] box = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                    Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
            Vec3 at = plane.point(), n = plane.normal();
            if (!frustum.widenToPlane(at.x(), at.y(), at.z(), n.x(), n.y(), n.z(), box)) {
                continue;
            }
            bounded++;
            for (int s = 0; s < 20; s++) {
                p.ray(s, random, ray);
                assertTrue(plane.intersect(ray, Double.POSITIVE_INFINITY, hit), "every ray of the pixel meets it");
                hits++;
                assertTrue(hit.px >= box[0] && hit.px <= box[3] && hit.py >= box[1] && hit.py <= box[4]
                        && hit.pz >= box[2] && hit.pz <= box[5], "the hit lies in the box");
            }
        }
        assertTrue(bounded > 300 && hits == 20 * bounded, "pixels whose part of the plane is bounded: " + bounded);
    }

    @Test
    void aPlaneSeenToTheHorizonOrFromAnEndedPyramidHasNoBoundedPart() {
        Frustum frustum = new Frustum();
        Camera camera = new Camera(new Vec3(0, 1, 5), new Vec3(0, 1, 0), new Vec3(0, 1, 0), 60);
        double[] box = {0, 0, 0, 0, 0, 0};
        // a pixel straddling the horizon of the floor y = 0
        camera.frustum(-0.01, 0.01, -0.01, 0.01, 1, frustum);
        assertFalse(frustum.widenToPlane(0, 0, 0, 0, 1, 0, box), "the pixel's top edge never meets the floor");
        // the same pixel below the horizon meets it in a bounded patch
        camera.frustum(-0.01, 0.01, -0.6, -0.58, 1, frustum);
        assertTrue(frustum.widenToPlane(0, 0, 0, 0, 1, 0, box));
        assertFalse(frustum.widenToPlane(0, 2, 0, 0, 1, 0, new double[6]), "a ceiling behind the pixel's rays");
        frustum.overBox(5, 5, 5, new double[] {0, 0, 0, 1, 1, 1});
        assertFalse(frustum.widenToPlane(0, 0, 0, 0, 1, 0, box), "a shadow pyramid has an end");
    }

    @Test
    void dropsNothingUntilToldTheBoxesMagnitude() {
        Camera camera = new Camera(new Vec3(0, 0, 5), Vec3.ZERO, new Vec3(0, 1, 0), 40);
        Frustum frustum = camera.frustum(-0.01, 0.01, -0.01, 0.01, 1, new Frustum());
        double[] aside = pointBox(3, 0, 0);

        assertTrue(frustum.mayMeet(aside, 0));
        assertFalse(frustum.within(3).mayMeet(aside, 0));
    }

    @Test
    void aBoxsPartInsideACameraPyramidHoldsEveryPointOfItOnTheRays() {
        Random random = new Random(9);
        Frustum frustum = new Frustum();
        Ray ray = new Ray();
        int tighter = 0, points = 0;
        for (int pixel = 0; pixel < 3000; pixel++) {
            Pixel p = Pixel.random(random, 0.5, 2, frustum);
            Camera camera = p.camera();
            // a box around a point on the pixel's middle ray, up to 100 times the distance across
            camera.ray(p.x0() + p.size() / 2, p.y0() + p.size() / 2, p.aspect(), ray);
            double t = Math.pow(10, uniform(random, -3, 4));
            double h = t * Math.pow(10, uniform(random, -5, 2));
            double cx = ray.ox + t * ray.dx, cy = ray.oy + t * ray.dy, cz = ray.oz + t * ray.dz;
            double[] shape = {cx - h * uniform(random, 0.1, 1), cy - h * uniform(random, 0.1, 1),
                    cz - h * uniform(random, 0.1, 1), cx + h * uniform(random, 0.1, 1), cy + h * uniform(random, 0.1, 1),
                    cz + h * uniform(random, 0.1, 1)};
            double[] part = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                    Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
            assertTrue(frustum.widenToPart(shape, 0, part));
            for (int s = 0; s < 40; s++) {
                p.ray(s, random, ray);
                double u = t * uniform(random, 0, 3);
                double px = ray.ox + u * ray.dx, py = ray.oy + u * ray.dy, pz = ray.oz + u * ray.dz;
                if (px < shape[0] || px > shape[3] || py < shape[1] || py > shape[4] || pz < shape[2] || pz > shape[5]) {
                    continue;
                }
                points++;
                assertTrue(px >= part[0] && px <= part[3] && py >= part[1] && py <= part[4]
                        && pz >= part[2] && pz <= part[5], "a point of the box on a ray of the pixel");
            }
            double kept = (part[3] - part[0]) * (part[4] - part[1]) * (part[5] - part[2]);
            double whole = (shape[3] - shape[0]) * (shape[4] - shape[1]) * (shape[5] - shape[2]);
            tighter += kept < whole / 2 ? 1 : 0;
        }
        assertTrue(points > 20000, "points tested: " + points);
        assertTrue(tighter > 1000, "parts less than half their box: " + tighter);
        frustum.overBox(5, 5, 5, new double[] {0, 0, 0, 1, 1, 1});
        assertFalse(frustum.widenToPart(new double[] {0, 0, 0, 1, 1, 1}, 0, new double[6]), "a shadow pyramid has an end");
    }

    @Test
    void aPyramidClearOfAPlaneHasNoRayOrSegmentThatMeetsIt() {
        Random random = new Random(10);
        Frustum frustum = new Frustum();
        Ray ray = new Ray();
        Hit hit = new Hit();
        int clear = 0, met = 0;
        for (int pixel = 0; pixel < 3000; pixel++) {
            Pixel p = Pixel.random(random, 0.5, 2, frustum);
            Vec3 eye = p.camera().position();
            double scale = Math.abs(eye.x()) + Math.abs(eye.y()) + 1;
            Plane plane = new Plane(eye.plus(randomPoint(random, scale)), randomPoint(random, 1));
            Vec3 at = plane.point(), n = plane.normal();
            boolean isClear = frustum.clearOf(at.x(), at.y(), at.z(), n.x(), n.y(), n.z());
            boolean anyMeets = false;
            for (int s = 0; s < 20; s++) {
                anyMeets |= plane.intersect(p.ray(s, random, ray), Double.POSITIVE_INFINITY, hit);
            }
            if (isClear) {
                clear++;
                assertFalse(anyMeets, "a camera ray meets a plane its pyramid is clear of");
            }
            met += anyMeets ? 1 : 0;
        }
        assertTrue(clear > 600 && met > 600, "clear of " + clear + ", met " + met);
        clear = 0;
        for (int i = 0; i < 3000; i++) {
            double scale = Math.pow(10, uniform(random, -2, 5));
            Vec3 c = randomPoint(random, scale);
            double h = scale * Math.pow(10, uniform(random, -4, -1));
            double[] box = {c.x() - h, c.y() - h, c.z() - h, c.x() + h, c.y() + h, c.z() + h};
            Vec3 light = c.plus(randomPoint(random, 1).normalized().times(scale * uniform(random, 0.05, 2)));
            if (!frustum.overBox(light.x(), light.y(), light.z(), box)) {
                continue;
            }
            Plane plane = new Plane(c.plus(randomPoint(random, 3 * h + scale * random.nextDouble())), randomPoint(random, 1));
            Vec3 at = plane.point(), n = plane.normal();
            if (!frustum.clearOf(at.x(), at.y(), at.z(), n.x(), n.y(), n.z())) {
                continue;
            }
            clear++;
            for (int s = 0; s < 20; s++) {
                double bx = uniform(random, box[0], box[3]), by = uniform(random, box[1], box[4]);
                double bz = uniform(random, box[2], box[5]);
                Vec3 d = light.minus(new Vec3(bx, by, bz));
                ray.set(bx, by, bz, d.x(), d.y(), d.z());
                assertFalse(plane.occluded(ray, 1), "a segment from the box to the light crosses the plane");
            }
        }
        assertTrue(clear > 600, "shadow pyramids clear of the plane: " + clear);
    }
}

package studio.engine.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.RayBundle;
import studio.engine.geometry.Rays;
import studio.engine.geometry.Shape;
import studio.engine.geometry.Sphere;
import studio.engine.math.Vec3;

/**
 * Shadow rays that carry the bundle of the camera rays whose hits they leave, through the pyramid
 * from the light over where those rays hit one object, are blocked exactly when the tree says so,
 * in scenes near the origin and 1e5 away from it, with lights above, beside and among the objects.
 */
class ShadowBundleTest {

    private static double uniform(Random random, double lo, double hi) {
        return lo + (hi - lo) * random.nextDouble();
    }

    /** Spheres and rotated boxes above a floor and before a back wall, all moved by offset. */
    private static Shape[] scene(Random random, int count, Vec3 offset) {
        Shape[] shapes = new Shape[count];
        shapes[0] = new Plane(offset, new Vec3(0, 1, 0));
        shapes[1] = new Plane(offset.plus(new Vec3(0, 0, -8)), new Vec3(0.05, 0, 1));
        for (int i = 2; i < count; i++) {
            Vec3 c = offset.plus(new Vec3(uniform(random, -6, 6), uniform(random, 0, 4), uniform(random, -7, 3)));
            shapes[i] = random.nextBoolean() ? new Sphere(c, uniform(random, 0.2, 1.2))
                    : new Box(c, new Vec3(uniform(random, 0.2, 2), uniform(random, 0.2, 2), uniform(random, 0.2, 2)),
                            new Vec3(uniform(random, -90, 90), uniform(random, -90, 90), 0));
        }
        return shapes;
    }

    @Test
    void shadowRaysThroughTheirBundlesAreBlockedExactlyWhenTheTreeSaysSo() {
        Random random = new Random(47);
        int rays = 0, listed = 0, blocked = 0;
        for (int round = 0; round < 8; round++) {
            Vec3 offset = round % 2 == 0 ? Vec3.ZERO : new Vec3(1e5, -3e4, 2e5);
            Shape[] shapes = scene(random, 10 + 6 * round, offset);
            List<Vec3> lights = List.of(offset.plus(new Vec3(-4, 9, 5)), offset.plus(new Vec3(12, 2, -1)),
                    offset.plus(new Vec3(0.5, 1.5, -2)));
            ShapeSet set = ShapeSet.of(lights, shapes), tree = ShapeSets.bvh(shapes);
            Camera camera = new Camera(offset.plus(new Vec3(uniform(random, -2, 2), 3, 10)),
                    offset.plus(new Vec3(0, 1, 0)), new Vec3(0, 1, 0), 50);
            Vec3 eye = camera.position();
            RayBundle cameraRays = new RayBundle();
            RayBundle[] shadowBundles = new RayBundle[lights.size()];
            Ray[] shadowRays = new Ray[lights.size()];
            for (int i = 0; i < lights.size(); i++) {
                shadowBundles[i] = RayBundle.towardsLight(shapes.length);
                shadowRays[i] = new Ray();
            }
            Hit hit = new Hit();
            int width = 64, height = 48;
            for (int y = 0; y < height; y++) {
                for (int x0 = 0; x0 < width; x0 += 4) {
                    camera.frustum(2.0 * x0 / width - 1, 2.0 * (x0 + 4) / width - 1, 1 - 2.0 * (y + 1) / height,
                            1 - 2.0 * y / height, (double) width / height, cameraRays.aim(eye.x(), eye.y(), eye.z()));
                    for (int s = 0; s < 8; s++) {
                        double px = x0 + 4 * random.nextDouble(), py = y + random.nextDouble();
                        Ray ray = camera.ray(2 * px / width - 1, 1 - 2 * py / height, (double) width / height);
                        ray.bundle = cameraRays;
                        if (!set.intersect(ray, Double.POSITIVE_INFINITY, hit)) {
                            continue;
                        }
                        for (int i = 0; i < lights.size(); i++) {
                            Vec3 light = lights.get(i);
                            Ray shadow = Rays.spawnTowards(hit, light.x(), light.y(), light.z(), shadowRays[i]);
                            double dx = light.x() - shadow.ox, dy = light.y() - shadow.oy, dz = light.z() - shadow.oz;
                            double tMax = Math.sqrt(dx * dx + dy * dy + dz * dz) * (1 - 1e-9);
                            boolean expected = tree.occluded(shadow, tMax);
                            shadow.bundle = shadowBundles[i].from(light.x(), light.y(), light.z(), cameraRays,
                                    hit.primitive);
                            assertEquals(expected, set.occluded(shadow, tMax), () -> "shadow ray " + shadow);
                            listed += shadowBundles[i].listedBy == set && shadowBundles[i].count >= 0 ? 1 : 0;
                            blocked += expected ? 1 : 0;
                            rays++;
                        }
                    }
                }
            }
        }
        assertTrue(rays > 50_000, "shadow rays: " + rays);
        assertTrue(listed > rays / 2, "through a list: " + listed + " of " + rays);
        assertTrue(blocked > rays / 10 && blocked < rays * 9 / 10, blocked + " of " + rays + " blocked");
    }

    @Test
    void aShadowBundleAboveTheFloorListsNeitherFloorNorWallAndAnswersAsTheTreeDoes() {
        Shape[] shapes = new Shape[12];
        shapes[0] = new Plane(Vec3.ZERO, new Vec3(0, 1, 0));
        shapes[1] = new Plane(new Vec3(0, 0, -8), new Vec3(0.05, 0, 1));
        for (int i = 2; i < shapes.length; i++) {
            shapes[i] = new Sphere(new Vec3(2.5 * (i - 7), 3 + 0.3 * (i % 3), -(i % 4)), 0.5);
        }
        ShapeSet set = ShapeSet.of(shapes), tree = ShapeSets.bvh(shapes);
        Camera camera = new Camera(new Vec3(0, 3, 10), new Vec3(0, 3, 0), new Vec3(0, 1, 0), 50);
        Vec3 eye = camera.position(), light = new Vec3(1, 20, 5);
        RayBundle cameraRays = new RayBundle(), shadows = RayBundle.towardsLight(shapes.length);
        camera.frustum(-0.02, 0.02, -0.02, 0.02, 1, cameraRays.aim(eye.x(), eye.y(), eye.z()));
        Random random = new Random(8);
        Hit hit = new Hit();
        Ray shadow = new Ray();
        int onSphere = 0;
        for (int s = 0; s < 200; s++) {
            Ray ray = camera.ray(uniform(random, -0.02, 0.02), uniform(random, -0.02, 0.02), 1);
            ray.bundle = cameraRays;
            if (!set.intersect(ray, Double.POSITIVE_INFINITY, hit) || !(shapes[hit.primitive] instanceof Sphere)) {
                continue;
            }
            onSphere++;
            Rays.spawnTowards(hit, light.x(), light.y(), light.z(), shadow);
            double tMax = light.minus(new Vec3(shadow.ox, shadow.oy, shadow.oz)).length() * (1 - 1e-9);
            boolean expected = tree.occluded(shadow, tMax);
            shadow.bundle = shadows.from(light.x(), light.y(), light.z(), cameraRays, hit.primitive);
            shadow.blocker = -1; // no cached answer: the list decides
            assertEquals(expected, set.occluded(shadow, tMax));
            assertTrue(shadows.listedBy == set, "listed by the set");
            assertTrue(shadows.count >= 0, "the shadow rays have a list: " + shadows.count);
            for (int k = 0; k < shadows.count; k++) {
                assertTrue(shadows.ids[k] >= 0, "no plane listed: " + shadows.ids[k]);
            }
        }
        assertTrue(onSphere > 100, "rays on the middle sphere: " + onSphere);
    }
}

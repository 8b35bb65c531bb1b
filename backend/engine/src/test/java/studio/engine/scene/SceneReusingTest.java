package studio.engine.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Sphere;
import studio.engine.light.Light;
import studio.engine.light.PointLight;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.render.Film;
import studio.engine.render.RenderRequest;
import studio.engine.render.RenderSettings;
import studio.engine.render.Renderer;
import studio.engine.sampler.RegularSampler;

/**
 * A scene assembled from the last one with a few objects changed ({@link Scene#reusing}) refits the
 * last one's tree and keeps its light buffers, and answers every ray as the scene built afresh does:
 * the same nearest hit, the same shadow, the same pixels; many changes build it again. Which one it
 * did shows in the bytes it allocates: a refit keeps the last tree's links and the light buffers.
 */
class SceneReusingTest {

    private static final Camera CAMERA = new Camera(new Vec3(0, 3, 12), new Vec3(0, 1, 0), new Vec3(0, 1, 0), 50);
    private static final List<Light> LIGHTS = List.of(new PointLight(new Vec3(4, 9, 5), Rgb.WHITE, 0.9, false),
            new PointLight(new Vec3(-6, 5, 3), new Rgb(0.6, 0.7, 1), 0.4, false));

    private static SceneObject sphere(Vec3 centre, double radius, MaterialKind kind) {
        return new SceneObject(new Sphere(centre, radius), MaterialDefaults.of(kind, new Rgb(0.8, 0.5, 0.3)));
    }

    /** A mirror ball in front, {@code n} small spheres and a few boxes behind it (a glass one among them), a floor. */
    private static List<SceneObject> objects(Random random, int n) {
        List<SceneObject> objects = new ArrayList<>();
        objects.add(sphere(new Vec3(0, 0.8, 2.5), 0.6, MaterialKind.MIRROR));
        for (int i = 1; i < n; i++) {
            Vec3 c = new Vec3(-4 + 8 * random.nextDouble(), 0.1 + 3 * random.nextDouble(), -4 + 6 * random.nextDouble());
            objects.add(i % 50 == 7 ? new SceneObject(new Box(c, new Vec3(0.3, 0.2, 0.4)),
                    MaterialDefaults.of(i == 7 ? MaterialKind.GLASS : MaterialKind.PLASTIC, new Rgb(0.2, 0.6, 0.3)))
                    : sphere(c, 0.1, i % 3 == 0 ? MaterialKind.CHALK : MaterialKind.METAL));
        }
        objects.add(new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)), MaterialDefaults.of(MaterialKind.CHALK, Rgb.WHITE)));
        return objects;
    }

    private static Scene fresh(List<SceneObject> objects) {
        return new Scene(CAMERA, objects, LIGHTS, new Rgb(0.1, 0.1, 0.1), 0.05);
    }

    private static Scene reusing(Scene last, List<SceneObject> objects) {
        return Scene.reusing(last, CAMERA, objects, LIGHTS, new Rgb(0.1, 0.1, 0.1), 0.05);
    }

    /** Object i moved to (x, y, z), its material kept. */
    private static void move(List<SceneObject> objects, int i, double x, double y, double z) {
        Sphere was = (Sphere) objects.get(i).shape();
        objects.set(i, new SceneObject(new Sphere(new Vec3(x, y, z), was.radius()), objects.get(i).material()));
    }

    /** Camera-like rays and shadow rays to both lights from random points: the same answers from both scenes. */
    private static void assertSameAnswers(Scene expected, Scene actual, Random random) {
        Hit a = new Hit(), b = new Hit();
        for (int k = 0; k < 20_000; k++) {
            Vec3 from = k % 2 == 0 ? CAMERA.position()
                    : new Vec3(-5 + 10 * random.nextDouble(), 0.01 + 4 * random.nextDouble(), -5 + 9 * random.nextDouble());
            Vec3 to = new Vec3(-5 + 10 * random.nextDouble(), 4 * random.nextDouble(), -5 + 8 * random.nextDouble());
            Vec3 d = to.minus(from).normalized();
            boolean hitA = expected.intersect(new Ray(from, d), Double.POSITIVE_INFINITY, a);
            boolean hitB = actual.intersect(new Ray(from, d), Double.POSITIVE_INFINITY, b);
            assertEquals(hitA, hitB, "ray " + k);
            if (hitA) {
                assertEquals(a.primitive, b.primitive, "ray " + k);
                assertEquals(a.t, b.t, 0, "ray " + k);
            }
            Vec3 light = LIGHTS.get(k % 2).position();
            Vec3 toLight = light.minus(from);
            double distance = toLight.length() * (1 - 1e-9);
            Vec3 unit = toLight.normalized();
            assertEquals(expected.occluded(new Ray(from, unit), distance), actual.occluded(new Ray(from, unit), distance),
                    "shadow ray " + k);
            assertEquals(expected.opaque().occluded(new Ray(from, unit), distance),
                    actual.opaque().occluded(new Ray(from, unit), distance), "opaque shadow ray " + k);
        }
    }

    @Test
    void aMovedObjectRefitsTheTreeKeepsTheBuffersAndAnswersAsAFreshScene() {
        Random random = new Random(45);
        List<SceneObject> objects = objects(random, 2000);
        Scene last = fresh(objects);
        long built = allocated(() -> fresh(objects));
        // a drag of the mirror ball, then of a small sphere through the others
        for (int step = 0; step < 12; step++) {
            move(objects, step < 6 ? 0 : 100, 0.3 * step - 1, 0.8, 2.5 - 0.4 * step);
            Scene before = last;
            long reused = allocated(() -> reusing(before, new ArrayList<>(objects)));
            assertTrue(reused < built / 2, "step " + step + ": refitted and the buffers kept, " + reused + " bytes against "
                    + built + " to build");
            Scene next = reusing(last, new ArrayList<>(objects));
            assertSameAnswers(fresh(objects), next, random);
            last = next;
        }
    }

    @Test
    void aRefittedSceneRendersThePixelsOfAFreshOne() {
        Random random = new Random(47);
        List<SceneObject> objects = objects(random, 600);
        Scene last = fresh(objects);
        move(objects, 0, 1.2, 0.7, 1.5);
        move(objects, 3, -0.5, 1.5, 0.5);
        RenderSettings settings = new RenderSettings(96, 72, new RegularSampler(1), 4, 2);
        Film reused = Renderer.render(RenderRequest.of(reusing(last, objects), settings)).film();
        Film built = Renderer.render(RenderRequest.of(fresh(objects), settings)).film();
        for (int y = 0; y < 72; y++) {
            for (int x = 0; x < 96; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(built.get(x, y, c), reused.get(x, y, c), 0, "pixel " + x + ", " + y);
                }
            }
        }
    }

    @Test
    void manyChangedObjectsBuildTheBuffersAgainAndAFarMoveTheTree() {
        Random random = new Random(46);
        List<SceneObject> objects = objects(random, 1000);
        Scene last = fresh(objects);
        long built = allocated(() -> fresh(objects));
        long[] steps = new long[StaleSlots.MAX + 1];
        for (int i = 1; i <= StaleSlots.MAX + 1; i++) {
            Sphere was = (Sphere) objects.get(10 * i).shape();
            move(objects, 10 * i, was.center().x() + 0.01, was.center().y(), was.center().z());
            Scene before = last;
            steps[i - 1] = allocated(() -> reusing(before, new ArrayList<>(objects)));
            last = reusing(last, new ArrayList<>(objects));
        }
        long kept = java.util.Arrays.stream(steps).min().getAsLong(), most = java.util.Arrays.stream(steps).max().getAsLong();
        assertTrue(most < built / 2, "the tree refitted at every step: " + most + " bytes against " + built);
        assertTrue(most > kept + kept / 5, "more than " + StaleSlots.MAX + " changed: the buffers are built again ("
                + most + " bytes against " + kept + " where they are kept)");
        assertSameAnswers(fresh(objects), last, random);
        // small spheres thrown far outside the scene: the refitted tree would cost too much, so it is built again
        for (int i = 0; i < 40; i++) {
            move(objects, 11 + i, 40 + i, 30 - i, -50 + 2 * i);
        }
        Scene before = last;
        long far = allocated(() -> reusing(before, new ArrayList<>(objects)));
        assertTrue(far > built * 3 / 4, "built again: " + far + " bytes against " + built);
        Scene rebuilt = reusing(last, new ArrayList<>(objects));
        assertSameAnswers(fresh(objects), rebuilt, random);
    }

    @Test
    void shadowRaysThroughKeptBuffersAndChangedSlotsAllocateNothing() {
        Random random = new Random(49);
        List<SceneObject> objects = objects(random, 1000);
        Scene last = fresh(objects);
        move(objects, 0, 0.5, 0.8, 2);
        move(objects, 5, -0.5, 1.8, 0);
        Scene scene = reusing(last, objects);
        Ray[] rays = new Ray[1024];
        double[] lengths = new double[rays.length];
        for (int i = 0; i < rays.length; i++) {
            Vec3 from = new Vec3(-4 + 8 * random.nextDouble(), 0.01 + 3 * random.nextDouble(), -4 + 6 * random.nextDouble());
            Vec3 toLight = LIGHTS.get(i % 2).position().minus(from);
            rays[i] = new Ray(from, toLight.normalized());
            lengths[i] = toLight.length() * (1 - 1e-9);
        }
        long blocked = shadows(scene, rays, lengths, 100_000); // warm-up: compiled before measuring
        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        long before = threads.getThreadAllocatedBytes(Thread.currentThread().getId());
        blocked += shadows(scene, rays, lengths, 100_000);
        long bytes = threads.getThreadAllocatedBytes(Thread.currentThread().getId()) - before;
        assertTrue(blocked > 0);
        assertTrue(bytes < 1024, "allocated " + bytes + " bytes over 100,000 shadow rays");
    }

    private static long shadows(Scene scene, Ray[] rays, double[] lengths, int calls) {
        long blocked = 0;
        for (int k = 0; k < calls; k++) {
            int i = k % rays.length;
            blocked += scene.opaque().occluded(rays[i], lengths[i]) ? 1 : 0;
        }
        return blocked;
    }

    @Test
    void changedLightsBuildTheBuffersAndAnUnchangedSceneSharesEverything() {
        Random random = new Random(48);
        List<SceneObject> objects = objects(random, 500);
        Scene first = fresh(objects);
        long built = allocated(() -> fresh(objects));
        long same = allocated(() -> reusing(first, objects));
        assertTrue(same < built / 2, "nothing changed: " + same + " bytes against " + built);
        assertSameAnswers(fresh(objects), reusing(first, objects), random);
        move(objects, 0, 1, 1, 1);
        long relitBytes = allocated(() -> Scene.reusing(first, CAMERA, objects, List.of(LIGHTS.get(1)), Rgb.BLACK, 0));
        assertTrue(relitBytes > same + same / 5, "new lights: new buffers, " + relitBytes + " bytes against " + same);
        assertTrue(relitBytes < built * 3 / 4, "the tree refitted all the same: " + relitBytes + " bytes against " + built);
        Scene relit = Scene.reusing(first, CAMERA, objects, List.of(LIGHTS.get(1)), Rgb.BLACK, 0);
        assertSame(objects.get(2).shape(), relit.shape(2));
    }

    /** The bytes this thread allocated making a scene (the scene's arrays: a refit keeps most of the last one's). */
    private static long allocated(java.util.function.Supplier<Scene> make) {
        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        long before = threads.getThreadAllocatedBytes(Thread.currentThread().getId());
        Scene made = make.get();
        long bytes = threads.getThreadAllocatedBytes(Thread.currentThread().getId()) - before;
        assertTrue(made != null);
        return bytes;
    }
}

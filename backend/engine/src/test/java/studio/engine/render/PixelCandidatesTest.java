package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Frustum;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Sphere;
import studio.engine.light.PointLight;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.sampler.Sampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/**
 * Listing what a pixel's rays can meet changes no pixel: every pixel of a cloud of 400 spheres and
 * boxes of every material, without a floor and over one (shadow lists then need the floor's part
 * in the pixel's pyramid), traced with the lists and with every ray searching the whole scene,
 * sums to the same bits.
 */
class PixelCandidatesTest {

    static Scene cloud(boolean floor) {
        Random random = new Random(11);
        List<SceneObject> objects = new ArrayList<>();
        if (floor) {
            objects.add(new SceneObject(new Plane(new Vec3(0, -0.2, 0), new Vec3(0, 1, 0)),
                    MaterialDefaults.of(MaterialKind.CHALK, new Rgb(0.7, 0.7, 0.7))));
        }
        MaterialKind[] kinds = MaterialKind.values();
        for (int i = 0; i < 400; i++) {
            Vec3 at = new Vec3(random.nextDouble() * 8 - 4, random.nextDouble() * 3, random.nextDouble() * 6 - 5);
            Rgb color = new Rgb(random.nextDouble(), random.nextDouble(), random.nextDouble());
            var material = MaterialDefaults.of(kinds[i % kinds.length], color);
            objects.add(new SceneObject(i % 4 == 0
                    ? new Box(at, new Vec3(0.2, 0.3, 0.2), new Vec3(0, 15 * i, 30))
                    : new Sphere(at, 0.05 + 0.2 * random.nextDouble()), material));
        }
        return new Scene(new Camera(new Vec3(0, 2, 6), new Vec3(0, 1.2, -1), new Vec3(0, 1, 0), 55), objects,
                List.of(new PointLight(new Vec3(5, 8, 4), Rgb.WHITE, 1, false),
                        new PointLight(new Vec3(0, 1.5, -1), new Rgb(1, 0.8, 0.5), 3, true)),
                new Rgb(0.1, 0.1, 0.15), 0.1);
    }

    /** 16 jittered samples, depth 4, one thread, fixed sampling. */
    private static RenderSettings jittered16(int width, int height) {
        return new RenderSettings(width, height, Sampler.of("jittered", 16), 4, 1, 1L,
                RenderSettings.DEFAULT_MIN_PATH_WEIGHT, 0);
    }

    /** The last call's sums of both tracers, to the bit. */
    private static void assertSameSums(SampleTracer searching, SampleTracer listing, String at) {
        assertEquals(searching.sumR, listing.sumR, 0.0, at);
        assertEquals(searching.sumG, listing.sumG, 0.0, at);
        assertEquals(searching.sumB, listing.sumB, 0.0, at);
    }

    /**
     * Traces every pixel at 16 jittered samples with lists and with every ray searching the whole
     * scene, asserting the same sums to the bit; returns how many pixels listed.
     */
    private static int listedPixelsSummingAlike(Scene scene, RenderSettings settings, long seed) {
        SampleTracer listing = new SampleTracer(scene, settings, new StopSignal());
        SampleTracer searching = new SampleTracer(scene, settings, new StopSignal()).withoutCandidates();
        Random random = new Random(seed);
        double[] xs = new double[16], ys = new double[16];
        int listed = 0;
        for (int y = 0; y < settings.height(); y++) {
            for (int x = 0; x < settings.width(); x++) {
                for (int s = 0; s < 16; s++) {
                    xs[s] = (s % 4 + random.nextDouble()) / 4;
                    ys[s] = (s / 4 + random.nextDouble()) / 4;
                }
                listing.trace(x, y, xs, ys, 0, 16);
                searching.trace(x, y, xs, ys, 0, 16);
                listed += listing.listedCandidates() ? 1 : 0;
                assertFalse(searching.listedCandidates());
                assertSameSums(searching, listing, "pixel " + x + ", " + y);
            }
        }
        return listed;
    }

    @Test
    void everyPixelSumsToTheSameBitsWithAndWithoutLists() {
        for (Scene scene : List.of(cloud(false), cloud(true))) {
            RenderSettings settings = jittered16(64, 48);
            int listed = listedPixelsSummingAlike(scene, settings, 5);
            assertTrue(listed > settings.width() * settings.height() / 2, "pixels that listed: " + listed);
            // (the rays counted may differ: a list may name a glass occluder first where the BVH
            // named an opaque one, and the walk through the glass then counts its rays)
        }
    }

    /**
     * Lists are kept for a run of pixels in a row: pixels visited in any order (as adaptive
     * sampling revisits them), with samples on their edges, still sum to the same bits.
     */
    @Test
    void pixelsVisitedInAnyOrderWithSamplesOnTheirEdgesSumToTheSameBits() {
        Scene scene = cloud(true);
        RenderSettings settings = jittered16(61, 45);
        SampleTracer listing = new SampleTracer(scene, settings, new StopSignal());
        SampleTracer searching = new SampleTracer(scene, settings, new StopSignal()).withoutCandidates();
        Random random = new Random(8);
        double[] xs = new double[8], ys = new double[8];
        double[] edges = {0, Math.nextDown(1.0), 1e-12, 0.5};
        int listed = 0;
        for (int k = 0; k < 6000; k++) {
            int x = random.nextInt(settings.width()), y = random.nextInt(settings.height());
            for (int s = 0; s < xs.length; s++) {
                xs[s] = s < 4 ? edges[s] : random.nextDouble();
                ys[s] = s < 4 ? edges[(s + k) % 4] : random.nextDouble();
            }
            int count = SampleTracer.CANDIDATES_FROM + random.nextInt(xs.length - SampleTracer.CANDIDATES_FROM + 1);
            listing.trace(x, y, xs, ys, 0, count);
            searching.trace(x, y, xs, ys, 0, count);
            listed += listing.listedCandidates() ? 1 : 0;
            assertSameSums(searching, listing, "pixel " + x + ", " + y);
        }
        assertTrue(listed > 3000, "pixels that listed: " + listed);
    }

    @Test
    void fewSamplesOrFewObjectsSearchAsBefore() {
        RenderSettings settings = new RenderSettings(640, 480, Sampler.of("jittered", 16), 4, 1, 1L,
                RenderSettings.DEFAULT_MIN_PATH_WEIGHT, 0);
        SampleTracer tracer = new SampleTracer(cloud(false), settings, new StopSignal());
        double[] xs = {0.1, 0.6, 0.3, 0.8}, ys = {0.2, 0.4, 0.7, 0.9};

        tracer.trace(320, 240, xs, ys, 0, SampleTracer.CANDIDATES_FROM - 1);
        assertFalse(tracer.listedCandidates(), "too few samples to repay the search");
        tracer.trace(320, 240, xs, ys, 0, SampleTracer.CANDIDATES_FROM);
        assertTrue(tracer.listedCandidates());

        Scene three = new Scene(new Camera(new Vec3(0, 0, 5), Vec3.ZERO, new Vec3(0, 1, 0), 40),
                List.of(new SceneObject(new Sphere(Vec3.ZERO, 1), MaterialDefaults.of(MaterialKind.CHALK, Rgb.WHITE))),
                List.of(), Rgb.BLACK, 0.1);
        SampleTracer small = new SampleTracer(three, settings, new StopSignal());
        small.trace(320, 240, xs, ys, 0, 4);
        assertFalse(small.listedCandidates(), "one object: the linear loop");
        Scene six = row(5, 1, 0);
        assertTrue(six.searchesBvh() && six.objectCount() < PixelCandidates.MIN_OBJECTS);
        SampleTracer fewer = new SampleTracer(six, settings, new StopSignal());
        fewer.trace(320, 240, xs, ys, 0, 4);
        assertFalse(fewer.listedCandidates(), "a BVH too small to repay listing");
    }

    /**
     * A scene of spheres, the first {@code along} one behind the other on the axis of the view, the
     * others beside it (1 to 3.1 to the left and right), and planes behind the camera: the centre
     * pixels' pyramid meets the spheres along the axis and no other.
     */
    private static Scene row(int spheres, int planes, int along) {
        List<SceneObject> objects = new ArrayList<>();
        var chalk = MaterialDefaults.of(MaterialKind.CHALK, Rgb.WHITE);
        for (int i = 0; i < planes; i++) {
            objects.add(new SceneObject(new Plane(new Vec3(0, 0, 20 + i), new Vec3(0, 0, -1)), chalk));
        }
        for (int i = 0; i < spheres; i++) {
            int j = i - along;
            double beside = (j % 2 == 0 ? 1 : -1) * (1 + 0.3 * (j / 2));
            Vec3 at = i < along ? new Vec3(0, 0, -2.0 * i) : new Vec3(beside, 0, 0);
            objects.add(new SceneObject(new Sphere(at, 0.2), chalk));
        }
        return new Scene(new Camera(new Vec3(0, 0, 8), Vec3.ZERO, new Vec3(0, 1, 0), 50), objects,
                List.of(new PointLight(new Vec3(0, 5, 8), Rgb.WHITE, 1, false)), Rgb.BLACK, 0.1);
    }

    @Test
    void lightsListsHoldAtMostLog2OfTheObjects() {
        assertEquals(0, PixelCandidates.longest(0));
        assertEquals(0, PixelCandidates.longest(1));
        assertEquals(2, PixelCandidates.longest(7));
        assertEquals(3, PixelCandidates.longest(8));
        assertEquals(4, PixelCandidates.longest(16));
        assertEquals(4, PixelCandidates.longest(31));
        assertEquals(13, PixelCandidates.longest(10_000));
        assertEquals(PixelCandidates.MAX, PixelCandidates.longest(1 << 20));
    }

    /** The centre pixel of 640x480, at 16 samples. */
    private static boolean centreListed(Scene scene) {
        RenderSettings settings = jittered16(640, 480);
        SampleTracer tracer = new SampleTracer(scene, settings, new StopSignal());
        double[] xs = new double[16], ys = new double[16];
        for (int s = 0; s < 16; s++) {
            xs[s] = (s % 4 + 0.5) / 4;
            ys[s] = (s / 4 + 0.5) / 4;
        }
        tracer.trace(320, 240, xs, ys, 0, 16);
        return tracer.listedCandidates();
    }

    @Test
    void aPixelWhosePyramidHoldsMoreThanACameraListSearchesTheTree() {
        // 40 objects: camera lists of at most 32; the centre pixels' pyramid holds the spheres along the axis
        assertTrue(centreListed(row(40, 0, 1)));
        assertTrue(centreListed(row(40, 0, PixelCandidates.CAMERA_MAX)));
        assertFalse(centreListed(row(40, 0, PixelCandidates.CAMERA_MAX + 1)));
    }

    /** The centre pixels' lists: the camera's length, and the light's (-1: none). */
    private static int[] centreLists(Scene scene) {
        PixelCandidates lists = new PixelCandidates(scene);
        lists.forCameraRaysIn(scene.camera().frustum(-0.001, 0.001, -0.001, 0.001, 4.0 / 3, new Frustum()));
        return new int[] {lists.cameraCount, lists.shadowCount(0)};
    }

    @Test
    void aCameraListLongerThanALightsMayBeLeavesItsShadowRaysToTheTree() {
        // 40 objects: a light's list holds at most 5; the camera list, nearest first, more
        assertArrayEquals(new int[] {5, 5}, centreLists(row(40, 0, 5)));
        assertArrayEquals(new int[] {6, -1}, centreLists(row(40, 0, 6)));
        PixelCandidates lists = new PixelCandidates(row(40, 0, 6));
        lists.forCameraRaysIn(row(40, 0, 6).camera().frustum(-0.001, 0.001, -0.001, 0.001, 4.0 / 3, new Frustum()));
        for (int k = 0; k < 6; k++) {
            assertEquals(k, lists.camera[k], "the spheres along the axis, nearest first");
        }
        for (int k = 1; k < 6; k++) {
            assertTrue(lists.cameraNear[k] > lists.cameraNear[k - 1] + 1.5, "2 apart, less their radii");
        }
    }

    @Test
    void planesThatFillTheLongestListLeaveTheSceneWithoutLists() {
        // 8 objects: lists of at most 3, and every list holds the planes
        assertFalse(PixelCandidates.pay(row(2, 6, 0)), "6 planes of 8 objects");
        assertFalse(PixelCandidates.pay(row(5, 3, 0)), "3 planes of 8 objects");
        assertTrue(PixelCandidates.pay(row(6, 2, 0)), "2 planes of 8 objects");
        assertTrue(centreListed(row(6, 2, 0)));
    }

    /** A small scene (16 objects: glass before boards over a floor), as the peer benchmark's glass. */
    @Test
    void aSmallSceneWithGlassSumsToTheSameBitsWithAndWithoutLists() {
        List<SceneObject> objects = new ArrayList<>();
        objects.add(new SceneObject(new Sphere(new Vec3(-1.2, 2.6, 0.5), 1.1),
                MaterialDefaults.of(MaterialKind.GLASS, Rgb.WHITE)));
        objects.add(new SceneObject(new Box(new Vec3(1.6, 2.6, 0.6), new Vec3(1.4, 1.4, 1.4), new Vec3(20, 35, 0)),
                MaterialDefaults.of(MaterialKind.GLASS, new Rgb(0.7, 0.9, 0.8))));
        objects.add(new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)),
                MaterialDefaults.of(MaterialKind.CHALK, new Rgb(0.4, 0.4, 0.35))));
        objects.add(new SceneObject(new Box(new Vec3(0, 3.25, -2.6), new Vec3(6, 6, 0.1)),
                MaterialDefaults.of(MaterialKind.CHALK, Rgb.WHITE)));
        for (int i = 0; i < 6; i++) {
            objects.add(new SceneObject(new Box(new Vec3(-2.5 + i, 3.25, -2.5), new Vec3(0.45, 6, 0.05)),
                    MaterialDefaults.of(MaterialKind.CHALK, new Rgb(0.1, 0.2, 0.5))));
            objects.add(new SceneObject(new Box(new Vec3(0, 0.75 + i, -2.48), new Vec3(6, 0.45, 0.05)),
                    MaterialDefaults.of(MaterialKind.PLASTIC, new Rgb(0.6, 0.1, 0.1))));
        }
        Scene scene = new Scene(new Camera(new Vec3(0, 3.2, 7), new Vec3(0, 3, 0), new Vec3(0, 1, 0), 45), objects,
                List.of(new PointLight(new Vec3(2, 6, 6), Rgb.WHITE, 0.9, false)), new Rgb(0.1, 0.1, 0.1), 0.15);
        assertEquals(16, scene.objectCount());
        RenderSettings settings = new RenderSettings(48, 36, Sampler.of("jittered", 16), 8, 1, 1L,
                RenderSettings.DEFAULT_MIN_PATH_WEIGHT, 0);
        int listed = listedPixelsSummingAlike(scene, settings, 3);
        assertTrue(listed > settings.width() * settings.height() / 4, "pixels that listed: " + listed);
    }
}

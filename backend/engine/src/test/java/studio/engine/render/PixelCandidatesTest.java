package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
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

    @Test
    void everyPixelSumsToTheSameBitsWithAndWithoutLists() {
        for (Scene scene : List.of(cloud(false), cloud(true))) {
            RenderSettings settings = jittered16(64, 48);
            SampleTracer listing = new SampleTracer(scene, settings, new StopSignal());
            SampleTracer searching = new SampleTracer(scene, settings, new StopSignal()).withoutCandidates();
            Random random = new Random(5);
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
        Scene sixty = OpaqueShadowsUnchangedTest.scene();
        assertTrue(sixty.searchesBvh() && sixty.objectCount() < PixelCandidates.MIN_OBJECTS);
        SampleTracer fewer = new SampleTracer(sixty, settings, new StopSignal());
        fewer.trace(320, 240, xs, ys, 0, 4);
        assertFalse(fewer.listedCandidates(), "a BVH too small to repay listing");
    }
}

package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Sphere;
import studio.engine.light.PointLight;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.sampler.JitteredSampler;
import studio.engine.sampler.Sampler;
import studio.engine.sampler.SobolSampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/**
 * A render stops within a tile: a cancel (or a deadline) that comes while a tile is being
 * rendered ends the render within a few camera samples, not when the tile is done, in each of the
 * three pixel loops, and a tile stopped on its ring leaves no edge pixel claimed for another tile
 * to wait on.
 */
class StopWithinTileTest {

    /** A stop must end the render this soon: a few samples of this scene take a few milliseconds. */
    private static final long STOP_MILLIS = 1_000;
    /** When the test asks the render to stop: well inside its first tile. */
    private static final long CANCEL_AFTER_MILLIS = 200;

    /**
     * Glass spheres between four mirrors, lit by 20 lights, 16 bounces deep: about a tenth of a
     * millisecond a camera sample on one thread, so one 16 x 16 tile at 256 samples takes 8 s or more.
     */
    private static final Scene HALL_OF_GLASS = hallOfGlass();

    @Test
    void aCancelInTheOnlyTileStopsTheFixedSampleRenderWithinASecond() {
        assertStopsWithinASecond(settings(16, new JitteredSampler(256), 0, 1));
    }

    @Test
    void aCancelInTheOnlyTileStopsTheAdaptiveRenderWithinASecond() {
        assertStopsWithinASecond(settings(16, new JitteredSampler(256), 1e-9, 1));
    }

    @Test
    void aCancelInTheOnlyTileStopsTheProgressiveSobolRenderWithinASecond() {
        assertStopsWithinASecond(settings(16, new SobolSampler(256), 1e-9, 1));
    }

    /**
     * Nine 16-pixel tiles on two threads share their edges' base samples: the tiles stopped while
     * they hold an edge pixel give it up, so the others do not wait for it (the render would hang).
     */
    @Test
    void tilesStoppedOnTheirRingsLeaveNoEdgePixelClaimed() {
        for (int cancelAfter : new int[] {0, 1, 5, 50, 200}) {
            assertTimeoutPreemptively(Duration.ofSeconds(20), () ->
                    assertStopsWithinASecond(settings(48, new SobolSampler(256), 1e-9, 2), cancelAfter));
        }
    }

    /** An expensive cancel condition (a socket read, say) is asked every few milliseconds, not every sample. */
    @Test
    void theCancelConditionIsAskedEveryFewMillisecondsNotEverySample() {
        AtomicInteger asked = new AtomicInteger();
        long start = System.nanoTime();
        long stopAt = start + CANCEL_AFTER_MILLIS * 1_000_000;
        BooleanSupplier cancelled = () -> {
            asked.incrementAndGet();
            return System.nanoTime() - stopAt > 0;
        };

        assertThrows(RenderCancelledException.class, () -> Renderer.render(RenderRequest.of(HALL_OF_GLASS, settings(16, new JitteredSampler(256), 0, 1)).cancelledWhen(cancelled)));

        long millis = (System.nanoTime() - start) / 1_000_000;
        // one tile: asked before it, then at most once per poll interval while it runs
        assertTrue(asked.get() <= 2 + millis / Renderer.POLL_MILLIS,
                "asked " + asked.get() + " times in " + millis + " ms");
    }

    private static void assertStopsWithinASecond(RenderSettings settings) {
        assertStopsWithinASecond(settings, CANCEL_AFTER_MILLIS);
    }

    private static void assertStopsWithinASecond(RenderSettings settings, long cancelAfterMillis) {
        long stopAt = System.nanoTime() + cancelAfterMillis * 1_000_000;
        assertThrows(RenderCancelledException.class, () -> Renderer.render(RenderRequest.of(HALL_OF_GLASS, settings).cancelledWhen(() -> System.nanoTime() - stopAt > 0)));
        long late = (System.nanoTime() - stopAt) / 1_000_000;
        assertTrue(late < STOP_MILLIS, settings.sampler() + " at threshold " + settings.adaptiveThreshold()
                + " on " + settings.threads() + " threads: the render ended " + late + " ms after its cancel");
    }

    private static RenderSettings settings(int size, Sampler sampler, double threshold, int threads) {
        return new RenderSettings(size, size, sampler, 16, threads, 7L, RenderSettings.DEFAULT_MIN_PATH_WEIGHT,
                threshold);
    }

    private static Scene hallOfGlass() {
        Random random = new Random(7);
        List<SceneObject> objects = new ArrayList<>();
        for (int i = 0; i < 60; i++) {
            objects.add(new SceneObject(new Sphere(new Vec3(random.nextDouble(-4, 4), random.nextDouble(0.3, 4),
                    random.nextDouble(-4, 4)), random.nextDouble(0.2, 0.5)),
                    MaterialDefaults.of(MaterialKind.GLASS, null)));
        }
        for (Vec3 normal : List.of(new Vec3(0, 0, 1), new Vec3(0, 0, -1), new Vec3(1, 0, 0), new Vec3(-1, 0, 0))) {
            objects.add(new SceneObject(new Plane(normal.times(-5), normal),
                    MaterialDefaults.of(MaterialKind.MIRROR, null)));
        }
        objects.add(new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)),
                MaterialDefaults.of(MaterialKind.CHALK, new Rgb(0.5, 0.5, 0.5))));
        List<PointLight> lights = new ArrayList<>();
        for (int i = 0; i < 20; i++) {
            lights.add(new PointLight(new Vec3(random.nextDouble(-4, 4), random.nextDouble(4, 6),
                    random.nextDouble(-4, 4)), Rgb.WHITE, 0.05, false));
        }
        return new Scene(new Camera(new Vec3(0, 2, 4.5), new Vec3(0, 1.5, 0), new Vec3(0, 1, 0), 60),
                objects, lights, new Rgb(0.1, 0.1, 0.1), 0.05);
    }
}

package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Sphere;
import studio.engine.light.PointLight;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.sampler.JitteredSampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/** Russian roulette on weak glass branches: counted so that nothing is lost on average, and the same draws every time. */
class BranchRouletteTest {

    private static final Vec3 UP = new Vec3(0, 1, 0);

    @Test
    void aBranchAtOrAboveTheThresholdIsAlwaysTracedOnce() {
        BranchRoulette roulette = new BranchRoulette(0.05, 7);
        roulette.startSample(3, 4, 0);
        for (double w : new double[] {0.05, 0.051, 0.5, 1}) {
            assertEquals(1.0, roulette.factor(w), 0.0, "weight " + w);
        }
    }

    @Test
    void withoutRouletteEveryBranchIsTracedOnce() {
        BranchRoulette none = BranchRoulette.none();
        for (double w : new double[] {1e-300, 1e-3, 0.01, 0.5}) {
            assertEquals(1.0, none.factor(w), 0.0, "weight " + w);
        }
    }

    @Test
    void aWeakBranchIsTracedWithProbabilityWeightOverThresholdAndCountsTheInverse() {
        BranchRoulette roulette = new BranchRoulette(0.05, 11);
        double weight = 0.01; // traced 1 time in 5, counted 5 times
        int n = 200_000, traced = 0;
        double sum = 0;
        for (int s = 0; s < n; s++) {
            roulette.startSample(s % 640, s / 640, s);
            double f = roulette.factor(weight);
            if (f > 0) {
                assertEquals(5.0, f, 1e-12);
                traced++;
            }
            sum += f;
        }
        // the mean factor estimates 1 with a standard deviation of 2 / sqrt(n) = 0.0045
        assertEquals(1.0, sum / n, 0.02);
        assertEquals(0.2, (double) traced / n, 0.005);
    }

    @Test
    void aSampleDrawsTheSameNumbersEveryTimeAndAnotherSampleOthers() {
        BranchRoulette a = new BranchRoulette(0.05, 99), b = new BranchRoulette(0.05, 99);
        StringBuilder first = new StringBuilder(), again = new StringBuilder(), other = new StringBuilder();
        for (int s = 0; s < 64; s++) {
            a.startSample(5, 6, s);
            b.startSample(5, 6, s);
            first.append(a.factor(0.02)).append(a.factor(0.02));
            again.append(b.factor(0.02)).append(b.factor(0.02));
            b.startSample(5, 6, s + 64);
            other.append(b.factor(0.02)).append(b.factor(0.02));
        }
        assertEquals(first.toString(), again.toString());
        assertNotEquals(first.toString(), other.toString());
    }

    @Test
    void aThresholdOutsideZeroToOneIsRejected() {
        for (double bad : new double[] {-0.1, 1.5, Double.NaN}) {
            assertThrows(IllegalArgumentException.class, () -> new BranchRoulette(bad, 0), "threshold " + bad);
        }
    }

    /**
     * A glass ball in front of a lit, coloured wall: camera rays through it split again and again
     * inside. With the roulette each ray's radiance is a random variable whose mean over many
     * samples is the radiance the full split gives (to within the minimum path weight's cut, which
     * both share), and fewer rays are traced.
     */
    @Test
    void throughAGlassBallTheMeanOfManySamplesIsTheFullSplitsRadianceWithFewerRays() {
        Scene scene = new Scene(new Camera(new Vec3(0, 0, 4), Vec3.ZERO, UP, 40), List.of(
                new SceneObject(new Sphere(Vec3.ZERO, 1), MaterialDefaults.of(MaterialKind.GLASS, Rgb.WHITE)),
                new SceneObject(new Plane(new Vec3(0, 0, -3), new Vec3(0, 0, 1)),
                        MaterialDefaults.of(MaterialKind.CHALK, new Rgb(0.9, 0.5, 0.2)))),
                List.of(new PointLight(new Vec3(2, 3, 4), Rgb.WHITE, 1, false)), new Rgb(0.6, 0.7, 0.9), 0.1);
        double minWeight = RenderSettings.DEFAULT_MIN_PATH_WEIGHT;
        for (double x : new double[] {0, 0.55, 0.9}) { // through the middle, off centre, near the rim
            Ray ray = new Ray(0, 0, 4, x, 0.1, -4);
            Integrator full = new Integrator(scene, 8, minWeight);
            Rgb expected = Radiance.of(full, ray);

            Integrator sampled = new Integrator(scene, 8, minWeight, new BranchRoulette(BranchRoulette.BELOW, 5));
            int n = 40_000;
            double r = 0, g = 0, b = 0;
            for (int s = 0; s < n; s++) {
                sampled.roulette.startSample(0, 0, s);
                Rgb c = Radiance.of(sampled, ray);
                r += c.r();
                g += c.g();
                b += c.b();
            }
            String where = "x " + x + ": full split " + expected;
            assertEquals(expected.r(), r / n, 0.01 * expected.r() + 1e-4, where);
            assertEquals(expected.g(), g / n, 0.01 * expected.g() + 1e-4, where);
            assertEquals(expected.b(), b / n, 0.01 * expected.b() + 1e-4, where);
            assertTrue(sampled.rays < n * full.rays, where + ": " + sampled.rays + " rays, full " + full.rays * n);
        }
    }

    @Test
    void aGlassRenderIsTheSameToTheBitOnOneThreadAndOnTwo() {
        Scene scene = MixedScene.SCENE;
        Film one = Renderer.render(RenderRequest.of(scene, new RenderSettings(48, 32, new JitteredSampler(8), 8, 1, 3L,
                RenderSettings.DEFAULT_MIN_PATH_WEIGHT))).film();
        Film two = Renderer.render(RenderRequest.of(scene, new RenderSettings(48, 32, new JitteredSampler(8), 8, 2, 3L,
                RenderSettings.DEFAULT_MIN_PATH_WEIGHT))).film();
        for (int y = 0; y < 32; y++) {
            for (int x = 0; x < 48; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(one.get(x, y, c), two.get(x, y, c), 0.0, "pixel " + x + "," + y);
                }
            }
        }
    }
}

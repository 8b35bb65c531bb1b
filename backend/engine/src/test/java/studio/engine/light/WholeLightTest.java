package studio.engine.light;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.geometry.Frustum;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;

/**
 * {@link WholeLight}: what all of a light gives a point
 * equals the mean of its samples (times the cosine at the point), where that mean is taken by a
 * fine midpoint rule over the sampler's (u, v), and the pyramid holds every segment to the light.
 */
class WholeLightTest {

    private static final Frustum PYRAMID = new Frustum();

    /** The mean over an n x n grid of (u, v) cell centres of what light 0 gives the point, times the cosine at its normal. */
    private static double sampledMean(LightSampler s, Vec3 p, Vec3 n, int grid) {
        double sum = 0;
        for (int i = 0; i < grid; i++) {
            for (int j = 0; j < grid; j++) {
                if (s.sample(0, p.x(), p.y(), p.z(), (i + 0.5) / grid, (j + 0.5) / grid)) {
                    double cos = n.x() * s.lx + n.y() * s.ly + n.z() * s.lz;
                    sum += Math.max(0, cos) * s.r;
                }
            }
        }
        return sum / ((double) grid * grid);
    }

    /** What all of the sampler's light 0 gives the point, or NaN where whole() declines. */
    private static double whole(Light light, Vec3 p, Vec3 n) {
        WholeLight w = new WholeLight(List.of(light));
        if (!w.whole(0, p.x(), p.y(), p.z(), n.x(), n.y(), n.z(), n.x(), n.y(), n.z(), PYRAMID)) {
            return Double.NaN;
        }
        w.light(0);
        return w.r;
    }

    private static Vec3 randomUnit(Random random) {
        Vec3 v = new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian());
        return v.normalized();
    }

    @Test
    void aSphereLightsAPointAsTheMeanOfItsSamples() {
        Random random = new Random(7);
        int checked = 0;
        for (int trial = 0; trial < 400 && checked < 40; trial++) {
            boolean falloff = trial % 2 == 0;
            Vec3 c = new Vec3(random.nextDouble() * 4 - 2, 2 + random.nextDouble() * 3, random.nextDouble() * 4 - 2);
            Light light = new SphereLight(c, 0.2 + random.nextDouble(), Rgb.WHITE, 2, falloff);
            LightSampler s = new LightSampler(List.of(light));
            Vec3 p = new Vec3(random.nextDouble() - 0.5, random.nextDouble() - 0.5, random.nextDouble() - 0.5);
            Vec3 n = randomUnit(random);
            double exact = whole(light, p, n);
            if (Double.isNaN(exact)) {
                continue;
            }
            assertEquals(sampledMean(s, p, n, 400), exact, 2e-5 * exact, "trial " + trial);
            checked++;
        }
        assertEquals(40, checked);
    }

    @Test
    void anAreaLightLightsAPointAsTheMeanOfItsSamples() {
        Random random = new Random(11);
        int[] checked = new int[2];
        for (int trial = 0; trial < 2000 && (checked[0] < 30 || checked[1] < 30); trial++) {
            boolean falloff = trial % 2 == 0;
            Vec3 position = new Vec3(random.nextDouble() * 2 - 1, 3 + random.nextDouble() * 2, random.nextDouble() * 2 - 1);
            Vec3 lookAt = new Vec3(random.nextDouble() * 2 - 1, 0, random.nextDouble() * 2 - 1);
            double width = 0.2 + 2 * random.nextDouble(), height = 0.2 + random.nextDouble();
            Light light = new AreaLight(position, width, height, lookAt, Rgb.WHITE, 2, falloff, trial % 3 == 0);
            LightSampler s = new LightSampler(List.of(light));
            Vec3 p = new Vec3(random.nextDouble() * 4 - 2, random.nextDouble() * 3, random.nextDouble() * 4 - 2);
            Vec3 n = randomUnit(random);
            double exact = whole(light, p, n);
            if (Double.isNaN(exact) || checked[falloff ? 1 : 0] >= 30) {
                continue;
            }
            assertEquals(sampledMean(s, p, n, 1000), exact, 3e-5 * exact, "trial " + trial + ", fall-off " + falloff);
            checked[falloff ? 1 : 0]++;
        }
        assertEquals(30, checked[0], "without fall-off");
        assertEquals(30, checked[1], "with fall-off");
    }

    @Test
    void aTinyAreaLightGivesWhatAPointLightOnItsAxisGives() {
        Vec3 at = new Vec3(0.5, 3, 0.25);
        Light light = new AreaLight(at, 1e-4, 1e-4, new Vec3(0.5, 0, 0.25), Rgb.WHITE, 3, true, false);
        Vec3 p = new Vec3(0.5, 0, 0.25), up = new Vec3(0, 1, 0);
        assertEquals(3.0 / 9, whole(light, p, up), 1e-9);
    }

    @Test
    void declinesWhereTheLightDipsBelowAHorizonOrThePointIsBehindIt() {
        Light area = new AreaLight(new Vec3(0, 2, 0), 2, 1, new Vec3(0, 0, 0), Rgb.WHITE, 1, false, false);
        Vec3 up = new Vec3(0, 1, 0);
        assertFalse(Double.isNaN(whole(area, new Vec3(0, 0, 0), up)));
        // the light straddles the horizon of a tilted point
        assertTrue(Double.isNaN(whole(area, new Vec3(0, 0, 0), new Vec3(1, 0.05, 0).normalized())));
        // behind a one-sided light
        assertTrue(Double.isNaN(whole(area, new Vec3(0, 3, 0), new Vec3(0, -1, 0))));
        // too near the plane of a light without fall-off for the quadrature: left to sampling
        assertTrue(Double.isNaN(whole(area, new Vec3(0, 1.6, 0), up)));
        Light sphere = new SphereLight(new Vec3(0, 1, 0), 0.5, Rgb.WHITE, 1, true);
        assertFalse(Double.isNaN(whole(sphere, new Vec3(0, 0, 0), up)));
        // a horizon through the cap, and a point inside the light
        assertTrue(Double.isNaN(whole(sphere, new Vec3(0, 0, 0), new Vec3(1, 0.2, 0).normalized())));
        assertTrue(Double.isNaN(whole(sphere, new Vec3(0, 1.2, 0), up)));
        // a point light has no whole to work out
        Light point = new PointLight(new Vec3(0, 1, 0), Rgb.WHITE, 1, true);
        assertTrue(Double.isNaN(whole(point, new Vec3(0, 0, 0), up)));
    }

    @Test
    void thePyramidHoldsEverySegmentToTheLight() {
        Random random = new Random(3);
        List<Light> lights = List.of(new SphereLight(new Vec3(0.5, 3, -0.5), 0.7, Rgb.WHITE, 1, false),
                new AreaLight(new Vec3(-0.5, 3, 0.5), 1.5, 0.6, new Vec3(0.2, 0, 0), Rgb.WHITE, 1, false, true));
        LightSampler s = new LightSampler(lights);
        WholeLight w = new WholeLight(lights);
        double[] box = new double[6];
        for (int light = 0; light < 2; light++) {
            Vec3 p = new Vec3(0.1, 0.2, -0.3), n = new Vec3(0, 1, 0);
            assertTrue(w.whole(light, p.x(), p.y(), p.z(), n.x(), n.y(), n.z(), n.x(), n.y(), n.z(), PYRAMID));
            PYRAMID.within(10);
            for (int k = 0; k < 2000; k++) {
                assertTrue(s.sample(light, p.x(), p.y(), p.z(), random.nextDouble(), random.nextDouble()));
                double f = random.nextDouble();
                // a tiny box around a point of the segment to the sample
                box[0] = box[3] = p.x() + f * (s.tx - p.x());
                box[1] = box[4] = p.y() + f * (s.ty - p.y());
                box[2] = box[5] = p.z() + f * (s.tz - p.z());
                assertTrue(PYRAMID.mayMeet(box, 0), "light " + light + ", sample " + k);
            }
            // a point beside the light is outside
            box[0] = box[3] = p.x() + 3;
            box[1] = box[4] = 3;
            box[2] = box[5] = p.z();
            assertFalse(PYRAMID.mayMeet(box, 0));
        }
    }
}

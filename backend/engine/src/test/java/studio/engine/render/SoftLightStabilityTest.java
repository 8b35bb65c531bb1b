package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Sphere;
import studio.engine.light.AreaLight;
import studio.engine.light.Light;
import studio.engine.light.PointLight;
import studio.engine.light.SphereLight;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Srgb;
import studio.engine.math.Vec3;
import studio.engine.sampler.JitteredSampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/** Where soft lights' methods fail (docs/robustness.md, LIGHT-01 to LIGHT-04). */
class SoftLightStabilityTest {

    private static final Rgb GREY = new Rgb(0.6, 0.6, 0.6);

    private static Scene ballOnFloor(Light light) {
        return new Scene(new Camera(new Vec3(0, 2, 6), new Vec3(0, 0.8, 0), new Vec3(0, 1, 0), 45),
                List.of(new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)), MaterialDefaults.of(MaterialKind.CHALK, GREY)),
                        new SceneObject(new Sphere(new Vec3(0, 1, 0), 1), MaterialDefaults.of(MaterialKind.PLASTIC,
                                new Rgb(0.8, 0.2, 0.1)))),
                List.of(light), new Rgb(0.1, 0.1, 0.15), 0.05);
    }

    private static Film render(Scene scene, int samples, int threads) {
        return Renderer.render(RenderRequest.of(scene, new RenderSettings(64, 48, new JitteredSampler(samples), 4, threads, 7L,
                RenderSettings.DEFAULT_MIN_PATH_WEIGHT))).film();
    }

    /** LIGHT-01: radius 1e-6 against the point light, every channel of every pixel in 8-bit sRGB. */
    @Test
    void aSphereLightOfRadiusOneMillionthIsThePointLightWithinOneLevel() {
        for (boolean falloff : new boolean[] {false, true}) {
            double intensity = falloff ? 40 : 0.9;
            Vec3 at = new Vec3(2, 5, 3);
            Film point = render(ballOnFloor(new PointLight(at, Rgb.WHITE, intensity, falloff)), 4, 2);
            Film sphere = render(ballOnFloor(new SphereLight(at, 1e-6, Rgb.WHITE, intensity, falloff)), 4, 2);
            int worst = 0;
            for (int y = 0; y < 48; y++) {
                for (int x = 0; x < 64; x++) {
                    for (int c = 0; c < 3; c++) {
                        worst = Math.max(worst, Math.abs(Srgb.toByte(point.get(x, y, c)) - Srgb.toByte(sphere.get(x, y, c))));
                    }
                }
            }
            assertTrue(worst <= 1, "falloff " + falloff + ": " + worst + " levels apart");
        }
    }

    /**
     * LIGHT-02: radius 100 with its surface 0.01 above a floor. No sample is NaN, and none is above
     * twice the pixel's mean (the estimate's largest factor is 2 / (1 + cos theta_max)): no fireflies.
     */
    @Test
    void aHugeLightJustAboveTheFloorGivesNoNanAndNoFireflies() {
        double d = 100.01;
        Scene scene = new Scene(new Camera(new Vec3(0, 0.005, 3), Vec3.ZERO, new Vec3(0, 1, 0), 40),
                List.of(new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)), MaterialDefaults.of(MaterialKind.CHALK, GREY))),
                List.of(new SphereLight(new Vec3(0, d, 0), 100, Rgb.WHITE, d * d, true)), Rgb.BLACK, 0);
        Integrator integrator = new Integrator(scene, 2, RenderSettings.DEFAULT_MIN_PATH_WEIGHT);
        double kd = MaterialDefaults.of(MaterialKind.CHALK, GREY).diffuse() * 0.6;
        for (double x : new double[] {0, 0.3, 2.5}) {
            double sum = 0, max = 0;
            int n = 32;
            for (int i = 0; i < n; i++) {
                for (int j = 0; j < n; j++) {
                    integrator.lightU = (i + 0.5) / n;
                    integrator.lightV = (j + 0.5) / n;
                    double v = Radiance.of(integrator, new Ray(x, 0.005, 0, 0, -1, 0)).r();
                    assertTrue(Double.isFinite(v));
                    sum += v;
                    max = Math.max(max, v);
                }
            }
            double mean = sum / (n * n);
            assertEquals(kd, mean, 0.01 * kd, "the irradiance of a sphere wholly above the horizon: I / d^2 = 1");
            assertTrue(max <= 2 * mean, "a firefly: " + max + " against a mean of " + mean);
        }
        RenderResult result = Renderer.render(RenderRequest.of(scene, new RenderSettings(32, 24, new JitteredSampler(4), 2, 2)));
        assertEquals(0, result.nonFiniteSamples());
    }

    /** LIGHT-03: a sphere light inside a glass ball lights the floor through the glass and is seen through it. */
    @Test
    void aLightInsideAGlassBallLightsTheFloorAndIsSeenThroughTheGlass() {
        Scene scene = new Scene(new Camera(new Vec3(0, 1.5, 6), new Vec3(0, 1.5, 0), new Vec3(0, 1, 0), 40),
                List.of(new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)), MaterialDefaults.of(MaterialKind.CHALK, GREY)),
                        new SceneObject(new Sphere(new Vec3(0, 1.5, 0), 1), MaterialDefaults.of(MaterialKind.GLASS, Rgb.WHITE))),
                List.of(new SphereLight(new Vec3(0, 1.5, 0), 0.2, new Rgb(1, 0.9, 0.8), 2, false)), Rgb.BLACK, 0);
        Integrator integrator = new Integrator(scene, 6, RenderSettings.DEFAULT_MIN_PATH_WEIGHT);
        integrator.lightU = 0.3;
        integrator.lightV = 0.6;

        Rgb floor = Radiance.of(integrator, new Ray(1.5, 0.2, 0, 0, -1, 0));
        Rgb seen = Radiance.of(integrator, new Ray(0, 1.5, 6, 0, 0, -1));

        assertTrue(floor.r() > 0.1 && floor.r() < 2 * 0.6, "the floor beside the ball, lit through the glass: " + floor);
        // through the glass's front at normal incidence, (1 - 0.04) of the emitter's colour * 2; the reflection sees black
        assertEquals(2 * 0.96, seen.r(), 1e-9, "the emitter seen through the glass: " + seen);
        assertEquals(2 * 0.96 * 0.8, seen.b(), 1e-9);
        RenderResult result = Renderer.render(RenderRequest.of(scene, new RenderSettings(32, 24, new JitteredSampler(4), 6, 2)));
        assertEquals(0, result.nonFiniteSamples());
    }

    /**
     * LIGHT-04: an area light seen exactly edge-on: the camera in its plane sees nothing of it (no
     * NaN, no streak), and a floor point in its plane gets nothing from it.
     */
    @Test
    void anAreaLightSeenEdgeOnShowsNothingAndLightsNothingInItsPlane() {
        AreaLight light = new AreaLight(new Vec3(0, 2, 0), 3, 3, Vec3.ZERO, Rgb.WHITE, 5, false, false);
        Rgb background = new Rgb(0.1, 0.2, 0.3);
        Scene scene = new Scene(new Camera(new Vec3(0, 2, 6), new Vec3(0, 2, 0), new Vec3(0, 1, 0), 40),
                List.of(new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)), MaterialDefaults.of(MaterialKind.CHALK, GREY)),
                        new SceneObject(new Plane(new Vec3(0, 0, -3), new Vec3(0, 0, 1)),
                                MaterialDefaults.of(MaterialKind.CHALK, GREY))),
                List.of(light), background, 0);
        Integrator integrator = new Integrator(scene, 2, RenderSettings.DEFAULT_MIN_PATH_WEIGHT);
        for (double u : new double[] {0.01, 0.5, 0.99}) {
            integrator.lightU = u;
            integrator.lightV = 1 - u;
            Rgb centre = Radiance.of(integrator, new Ray(0, 2, 6, 0, 0, -1));
            assertEquals(0, centre.r(), "the wall behind, where the light's plane meets it, gets nothing: " + centre);
            assertTrue(Radiance.of(integrator, new Ray(0, 1, 0, 0, -1, 0)).r() > 0, "the floor under it is lit");
        }
        RenderResult result = Renderer.render(RenderRequest.of(scene, new RenderSettings(33, 25, new JitteredSampler(4), 2, 2)));
        assertEquals(0, result.nonFiniteSamples());
    }
}

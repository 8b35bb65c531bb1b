package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Sphere;
import studio.engine.light.PointLight;
import studio.engine.material.Fresnel;
import studio.engine.material.Material;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.sampler.JitteredSampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/**
 * Robustness case OPT-01: refraction, total internal reflection and energy at a glass interface, and a glass cube
 * render in which most first exits are totally reflected. The interface is the plane y = 0 with glass
 * (n = 1.5) below it; flat red above and flat green below show where the light went.
 */
class GlassOpticsTest {

    private static final Vec3 UP = new Vec3(0, 1, 0);
    private static final Material GLASS = MaterialDefaults.of(MaterialKind.GLASS, Rgb.WHITE);
    private static final SceneObject INTERFACE = new SceneObject(new Plane(Vec3.ZERO, UP), GLASS);
    private static final SceneObject RED_ABOVE = new SceneObject(new Plane(new Vec3(0, 2, 0), UP),
            MaterialDefaults.of(MaterialKind.FLAT, new Rgb(1, 0, 0)));
    private static final SceneObject GREEN_BELOW = new SceneObject(new Plane(new Vec3(0, -2, 0), UP),
            MaterialDefaults.of(MaterialKind.FLAT, new Rgb(0, 1, 0)));

    /** A ray inside the glass going up to the origin at angle theta from the normal. */
    private static Ray upward(double theta) {
        return new Ray(-Math.sin(theta), -Math.cos(theta), 0, Math.sin(theta), Math.cos(theta), 0);
    }

    @Test
    void leavingGlassBeyondTheCriticalAngleIsReflectedWhole() {
        for (double degrees : new double[] {41.8103148958, 45, 60, 89.9}) {
            Rgb c = trace(List.of(INTERFACE, RED_ABOVE, GREEN_BELOW), upward(Math.toRadians(degrees)));

            assertEquals(new Rgb(0, 1, 0), c, degrees + " deg");
        }
    }

    @Test
    void leavingGlassBelowTheCriticalAngleSplitsByFresnelWithNothingLost() {
        double theta = Math.toRadians(30);
        Rgb c = trace(List.of(INTERFACE, RED_ABOVE, GREEN_BELOW), upward(theta));

        double r = Fresnel.reflectance(Math.cos(theta), 1.5, 1);
        assertEquals(r, c.g(), 1e-15, "reflected back into the glass");
        assertEquals(1 - r, c.r(), 1e-15, "transmitted into the air");
    }

    @Test
    void raysWithinAPicoradianOfTheCriticalAngleStayFiniteAndConserveEnergy() {
        double critical = Math.asin(1 / 1.5);
        for (int k = 0; k <= 2000; k++) {
            double theta = critical - 1e-12 + 2e-12 * k / 2000;
            Rgb c = trace(List.of(INTERFACE, RED_ABOVE, GREEN_BELOW), upward(theta));

            assertTrue(Double.isFinite(c.r()) && Double.isFinite(c.g()), "ray " + k + ": " + c);
            assertEquals(1.0, c.r() + c.g(), 1e-12, "ray " + k + ": " + c);
            assertTrue(c.g() >= 0.99, "ray " + k + ": " + c);
        }
    }

    @Test
    void refractedRayBendsAsSnellsLawSays() {
        // Out of the glass at 30 deg: sin t = 1.5 * 0.5 = 0.75. Into the glass at 45 deg: sin t = sqrt(0.5) / 1.5.
        double sinOut = 0.75, sinIn = Math.sqrt(0.5) / 1.5;
        Vec3 out = new Vec3(sinOut, Math.sqrt(1 - sinOut * sinOut), 0);
        Vec3 in = new Vec3(sinIn, -Math.sqrt(1 - sinIn * sinIn), 0);
        Material blue = MaterialDefaults.of(MaterialKind.FLAT, new Rgb(0, 0, 1));

        Rgb leaving = trace(List.of(INTERFACE, new SceneObject(new Sphere(out.times(3), 0.03), blue)),
                upward(Math.toRadians(30)));
        Rgb entering = trace(List.of(INTERFACE, new SceneObject(new Sphere(in.times(3), 0.03), blue)),
                new Ray(-1, 1, 0, 1, -1, 0));

        assertEquals(1 - Fresnel.reflectance(Math.sqrt(0.75), 1.5, 1), leaving.b(), 1e-15);
        assertEquals(1 - Fresnel.reflectance(Math.sqrt(0.5), 1, 1.5), entering.b(), 1e-15);
    }

    @Test
    void glassCubeOnWhiteCreatesNoLightAlongAnyRay() {
        // White background, clear glass, no lights: every path ends on the background with weight <= 1.
        Scene scene = glassCubeOnWhite();
        Integrator integrator = new Integrator(scene, 12, 0);
        Ray ray = new Ray();
        for (int y = 0; y < 128; y++) {
            for (int x = 0; x < 128; x++) {
                Rgb c = Radiance.of(integrator, pixelCentre(scene, x, y, ray));
                for (double v : new double[] {c.r(), c.g(), c.b()}) {
                    assertTrue(v >= 0 && v <= 1 + 1e-12, "pixel " + x + "," + y + " = " + c);
                }
            }
        }
    }

    @Test
    void glassCubeOnWhiteRendersWithoutNonFiniteSamplesAndAsBrightAsTheFullSplit() {
        // A render plays the roulette on weak branches: a pixel may come out a little above 1, while
        // the image's mean is the full split's (traced here through the pixels' centres).
        Scene scene = glassCubeOnWhite();
        Integrator fullSplit = new Integrator(scene, 12, 0);
        Ray ray = new Ray();
        double fullSum = 0;
        for (int y = 0; y < 128; y++) {
            for (int x = 0; x < 128; x++) {
                Rgb c = Radiance.of(fullSplit, pixelCentre(scene, x, y, ray));
                fullSum += c.r() + c.g() + c.b();
            }
        }

        RenderResult result = Renderer.render(RenderRequest.of(scene, new RenderSettings(128, 128, new JitteredSampler(4), 12, 2,
                1L, 0)));

        assertEquals(0, result.nonFiniteSamples());
        Film film = result.film();
        double sum = 0;
        for (int y = 0; y < 128; y++) {
            for (int x = 0; x < 128; x++) {
                for (int ch = 0; ch < 3; ch++) {
                    double v = film.get(x, y, ch);
                    assertTrue(v >= 0 && v < 1.5, "pixel " + x + "," + y + " = " + v);
                    sum += v;
                }
            }
        }
        double mean = sum / (3 * 128 * 128), fullMean = fullSum / (3 * 128 * 128);
        assertEquals(fullMean, mean, 0.005 * fullMean, "the image's mean against the full split's");
        assertTrue(mean <= 1, "mean " + mean);
        assertEquals(1.0, film.get(0, 0, 0), 0.0, "background corner");
        assertTrue(film.get(64, 64, 0) > 0.2, "the cube's centre is not black: " + film.get(64, 64, 0));
    }

    /** The camera ray through the centre of pixel (x, y) of a 128x128 image, into {@code out}. */
    private static Ray pixelCentre(Scene scene, int x, int y, Ray out) {
        return scene.camera().ray(2 * (x + 0.5) / 128 - 1, 1 - 2 * (y + 0.5) / 128, 1, out);
    }

    private static Scene glassCubeOnWhite() {
        Camera camera = new Camera(new Vec3(3, 2.5, 4), Vec3.ZERO, UP, 40);
        return new Scene(camera, List.of(new SceneObject(new Box(Vec3.ZERO, new Vec3(2, 2, 2)), GLASS)),
                List.of(), Rgb.WHITE, 0.1);
    }

    @Test
    void glassCubeOverALitFloorRendersWithoutNonFiniteSamples() {
        Camera camera = new Camera(new Vec3(3, 2.5, 4), Vec3.ZERO, UP, 40);
        Scene scene = new Scene(camera, List.of(
                new SceneObject(new Box(Vec3.ZERO, new Vec3(2, 2, 2)), MaterialDefaults.of(MaterialKind.GLASS,
                        new Rgb(0.9, 0.95, 1))),
                new SceneObject(new Plane(new Vec3(0, -1, 0), UP), MaterialDefaults.of(MaterialKind.CHALK,
                        new Rgb(0.8, 0.8, 0.8)))),
                List.of(new PointLight(new Vec3(2, 6, 3), Rgb.WHITE, 1, false)), new Rgb(0.2, 0.3, 0.5), 0.1);

        RenderResult result = Renderer.render(RenderRequest.of(scene, new RenderSettings(128, 128, new JitteredSampler(4), 12, 2)));

        assertEquals(0, result.nonFiniteSamples());
    }

    private static Rgb trace(List<SceneObject> objects, Ray ray) {
        Scene scene = new Scene(new Camera(new Vec3(0, 1, 5), Vec3.ZERO, UP, 45), objects,
                List.<PointLight>of(), Rgb.BLACK, 0.1);
        return Radiance.of(new Integrator(scene, 3, 0), ray);
    }
}

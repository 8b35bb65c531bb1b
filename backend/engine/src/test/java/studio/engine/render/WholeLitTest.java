package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Sphere;
import studio.engine.light.AreaLight;
import studio.engine.light.Light;
import studio.engine.light.SphereLight;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.sampler.SobolSampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/**
 * A point that sees all of a light gets its exact light, with no shadow ray and no noise; a point
 * in a penumbra is still sampled. A floor, a box beside the light's cone from the origin (x = 1.2
 * to 1.6) and, in some scenes, more shapes; the light above the origin at height 4.
 */
class WholeLitTest {

    private static final SceneObject FLOOR = new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)),
            MaterialDefaults.of(MaterialKind.CHALK, Rgb.WHITE));
    private static final SceneObject BOX = new SceneObject(new Box(new Vec3(1.4, 1, 0), new Vec3(0.4, 2, 0.4)),
            MaterialDefaults.of(MaterialKind.CHALK, Rgb.WHITE));

    private static Scene scene(Light light, SceneObject... more) {
        List<SceneObject> objects = new ArrayList<>(List.of(FLOOR, BOX));
        objects.addAll(List.of(more));
        return new Scene(new Camera(new Vec3(0, 2, 5), Vec3.ZERO, new Vec3(0, 1, 0), 40), objects, List.of(light),
                Rgb.BLACK, 0);
    }

    private static final List<Light> LIGHTS = List.of(
            new AreaLight(new Vec3(0, 4, 0), 1, 1, Vec3.ZERO, Rgb.WHITE, 1, false, false),
            new AreaLight(new Vec3(0, 4, 0), 1, 1, Vec3.ZERO, Rgb.WHITE, 1, true, false),
            new SphereLight(new Vec3(0, 4, 0), 0.5, Rgb.WHITE, 1, false),
            new SphereLight(new Vec3(0, 4, 0), 0.5, Rgb.WHITE, 1, true));

    /** The integrator, trying lights whole (as under adaptive sampling). */
    private static Integrator whole(Integrator integrator) {
        integrator.wholeLights = true;
        return integrator;
    }

    /** The red radiance at floor point (x, 0, z) seen from straight above, with the light sample (u, v). */
    private static double at(Integrator integrator, double x, double z, double u, double v) {
        integrator.lightU = u;
        integrator.lightV = v;
        integrator.startRun();
        return Radiance.of(integrator, new Ray(x, 0.5, z, 0, -1, 0)).r();
    }

    @Test
    void aWhollyLitPointGetsTheSameLightFromEverySampleAndTracesNoShadowRay() {
        for (Light light : LIGHTS) {
            Integrator integrator = whole(new Integrator(scene(light), 1, 0));
            double first = at(integrator, 0.2, 0.1, 0.5, 0.5);
            assertTrue(first > 0);
            long rays = integrator.rays;
            for (double u : new double[] {0.01, 0.37, 0.99}) {
                for (double v : new double[] {0.02, 0.61, 0.98}) {
                    assertEquals(first, at(integrator, 0.2, 0.1, u, v), light.toString());
                }
            }
            assertEquals(9, integrator.rays - rays, "a camera ray each, no shadow ray: " + light);
        }
    }

    @Test
    void withoutAdaptiveSamplingEveryPointTracesItsShadowRay() {
        Integrator integrator = new Integrator(scene(LIGHTS.get(0)), 1, 0);
        long rays = integrator.rays;
        double a = at(integrator, 0.2, 0.1, 0.01, 0.02), b = at(integrator, 0.2, 0.1, 0.99, 0.98);
        assertEquals(4, integrator.rays - rays);
        assertTrue(a != b, "each sample its own light point");
    }

    @Test
    void aOneSampleRenderIsTheSameWithOrWithoutAThreshold() {
        // at one sample a pixel a threshold changes nothing (RenderSettings.adaptive), so neither does the whole light
        for (Light light : LIGHTS) {
            Film fixed = Renderer.render(RenderRequest.of(scene(light),
                    new RenderSettings(40, 30, new SobolSampler(1), 2, 1, 7, 0, 0))).film();
            Film thresholded = Renderer.render(RenderRequest.of(scene(light),
                    new RenderSettings(40, 30, new SobolSampler(1), 2, 1, 7, 0, 0.05))).film();
            for (int y = 0; y < 30; y++) {
                for (int x = 0; x < 40; x++) {
                    for (int c = 0; c < 3; c++) {
                        assertEquals(fixed.get(x, y, c), thresholded.get(x, y, c), light + " at " + x + ", " + y);
                    }
                }
            }
        }
    }

    @Test
    void aPointInAPenumbraIsStillSampled() {
        for (Light light : LIGHTS) {
            // the box, 2 m tall, stands between (3.2, 0, 0) and part of the light
            Integrator integrator = whole(new Integrator(scene(light), 1, 0));
            double least = Double.POSITIVE_INFINITY, most = 0;
            for (int i = 0; i < 5; i++) {
                for (int j = 0; j < 5; j++) {
                    double r = at(integrator, 3.2, 0, (i + 0.5) / 5, (j + 0.5) / 5);
                    least = Math.min(least, r);
                    most = Math.max(most, r);
                }
            }
            assertEquals(0, least, light.toString());
            assertTrue(most > 0, light.toString());
        }
    }

    @Test
    void anyShapeInThePyramidLeavesThePointToSampling() {
        // a small sphere and a small glass box inside the pyramid from the point to the light, and a sloping plane across it
        SceneObject[] blockers = {
            new SceneObject(new Sphere(new Vec3(0.4, 3.5, 0.4), 0.01), MaterialDefaults.of(MaterialKind.CHALK, Rgb.WHITE)),
            new SceneObject(new Box(new Vec3(-0.4, 3.5, -0.4), new Vec3(0.01, 0.01, 0.01)),
                    MaterialDefaults.of(MaterialKind.GLASS, Rgb.WHITE)),
            new SceneObject(new Plane(new Vec3(0, 3.9, 0), new Vec3(0.05, 1, 0)), MaterialDefaults.of(MaterialKind.CHALK, Rgb.WHITE)),
        };
        Light light = LIGHTS.get(0);
        double open = at(whole(new Integrator(scene(light), 1, 0)), 0, 0, 0.5, 0.5);
        for (SceneObject blocker : blockers) {
            Integrator integrator = whole(new Integrator(scene(light, blocker), 1, 0));
            long rays = integrator.rays;
            at(integrator, 0, 0, 0.5, 0.5);
            assertTrue(integrator.rays - rays >= 2, "a shadow ray beside the camera ray: " + blocker.shape());
        }
        assertTrue(open > 0);
    }
}

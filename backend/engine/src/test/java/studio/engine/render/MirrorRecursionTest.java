package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.material.Material;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/**
 * Robustness case OPT-03: a ray between two parallel mirrors. Each hit adds 0.1 (ambient 1 times diffuse 0.1) and
 * reflects half, so the value is the geometric sum 0.1 * (1 - 0.5^(D+1)) / 0.5 over the D + 1 hits.
 */
class MirrorRecursionTest {

    private static final Material HALF_MIRROR = MaterialDefaults.of(MaterialKind.METAL, Rgb.WHITE, 0.1, 0.0, 1.0,
            0.5, null);
    private static final Scene MIRRORS = new Scene(
            new Camera(new Vec3(0.2, -0.3, 0.71), new Vec3(0.5, -0.2, 0), new Vec3(0, 1, 0), 40),
            List.of(new SceneObject(new Plane(new Vec3(0, 0, 0.1), new Vec3(0, 0, 1)), HALF_MIRROR),
                    new SceneObject(new Plane(new Vec3(0, 0, 1.37), new Vec3(0, 0, -1)), HALF_MIRROR)),
            List.of(), Rgb.BLACK, 1.0);
    private static final Ray RAY = new Ray(new Vec3(0.2, -0.3, 0.71), new Vec3(0.3, 0.1, -1).normalized());

    @Test
    void parallelMirrorsSumEveryBounceUpToTheDepthLimit() {
        for (int depth : new int[] {0, 1, 5, 20, 40}) {
            Integrator integrator = new Integrator(MIRRORS, depth, 0);

            Rgb c = Radiance.of(integrator, RAY);

            double expected = 0.1 * (1 - Math.pow(0.5, depth + 1)) / 0.5;
            assertEquals(expected, c.r(), 1e-9, "maxDepth " + depth);
            assertEquals(c.r(), c.b(), 0.0);
            assertEquals(depth + 1, integrator.rays, "one ray per bounce, none re-hitting its own mirror");
        }
        assertEquals(0.199999905, Radiance.of(new Integrator(MIRRORS, 20, 0), RAY).g(), 1e-9);
    }

    @Test
    void deeperRecursionChangesTheValueByLessThanTheDroppedTail() {
        double d20 = Radiance.of(new Integrator(MIRRORS, 20, 0), RAY).r();
        double d40 = Radiance.of(new Integrator(MIRRORS, 40, 0), RAY).r();

        assertTrue(Math.abs(d40 - d20) < 1e-6, d20 + " vs " + d40);
    }

    @Test
    void minimumPathWeightStopsBouncesThatCannotChangeThePixel() {
        Integrator integrator = new Integrator(MIRRORS, 40, RenderSettings.DEFAULT_MIN_PATH_WEIGHT);

        Rgb c = Radiance.of(integrator, RAY);

        // the ray after hit k carries weight 0.5^(k+1), traced only while above 1/1024: hits 0 to 9
        assertEquals(10, integrator.rays);
        assertEquals(0.1 * (1 - Math.pow(0.5, 10)) / 0.5, c.r(), 1e-12);
    }
}

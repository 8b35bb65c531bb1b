package studio.engine.light;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.geometry.Box;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Shape;
import studio.engine.geometry.Sphere;
import studio.engine.geometry.TriangleMesh;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.mesh.MeshShapes;

/**
 * {@link LightSampler#hiddenBy}: whether one object hides all of a sphere or area light from a point
 * (an umbra), checked against the light's own samples on a fine grid, where it fails if anywhere:
 * blockers that just cover the light, that just miss a corner, seen at a slant.
 */
class UmbraTest {

    private static final Vec3 UP = new Vec3(0, 4, 0);
    private final Ray probe = new Ray();

    private static LightSampler sphere(double radius) {
        return new LightSampler(List.of(new SphereLight(UP, radius, Rgb.WHITE, 1, true)));
    }

    private static LightSampler area(double width, double height) {
        return new LightSampler(List.of(new AreaLight(UP, width, height, new Vec3(0.3, 0, 0.2), Rgb.WHITE, 1, true, false)));
    }

    /** Whether any of n x n samples of light 0 is seen from (px, py, pz) past the blocker. */
    private static boolean anySampleSeen(LightSampler lights, Shape blocker, double px, double py, double pz, int n) {
        Ray ray = new Ray();
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                if (!lights.sample(0, px, py, pz, (i + 0.5) / n, (j + 0.5) / n)) {
                    continue;
                }
                double x = lights.tx - px, y = lights.ty - py, z = lights.tz - pz;
                double dist = Math.sqrt(x * x + y * y + z * z);
                if (!blocker.occluded(ray.set(px, py, pz, x / dist, y / dist, z / dist), dist * (1 - 1e-9))) {
                    return true;
                }
            }
        }
        return false;
    }

    @Test
    void aBoardWideEnoughHidesASphereLightAndANarrowOneDoesNot() {
        LightSampler lights = sphere(0.5);
        Box wide = new Box(new Vec3(0, 2, 0), new Vec3(3, 0.1, 3));
        Box narrow = new Box(new Vec3(0, 2, 0), new Vec3(0.3, 0.1, 0.3));

        assertTrue(lights.hiddenBy(0, wide, 0, 0, 0, probe));
        assertFalse(anySampleSeen(lights, wide, 0, 0, 0, 64));
        assertFalse(lights.hiddenBy(0, narrow, 0, 0, 0, probe));
        assertTrue(anySampleSeen(lights, narrow, 0, 0, 0, 64), "a penumbra: part of the light is seen");
    }

    @Test
    void aBallAndAPlaneAreConvexAMeshIsNotAndAPointLightHasNoUmbraToTell() {
        LightSampler lights = sphere(0.5);
        Sphere ball = new Sphere(new Vec3(0, 2, 0), 1);
        Plane ceiling = new Plane(new Vec3(0, 2, 0), new Vec3(0, -1, 0));
        TriangleMesh mesh = new TriangleMesh(MeshShapes.icosphere(3), new Vec3(0, 2, 0), 1, Vec3.ZERO);

        assertTrue(lights.hiddenBy(0, ball, 0, 0, 0, probe));
        assertTrue(lights.hiddenBy(0, ceiling, 0, 0, 0, probe));
        assertFalse(anySampleSeen(lights, mesh, 0, 0, 0, 32), "the mesh does hide the light");
        assertFalse(lights.hiddenBy(0, mesh, 0, 0, 0, probe), "but a mesh is not asked");
        LightSampler point = new LightSampler(List.of(new PointLight(UP, Rgb.WHITE, 1, true)));
        assertFalse(point.hiddenBy(0, ball, 0, 0, 0, probe));
    }

    @Test
    void aBlockerBeyondTheSphereLightsNearSideHidesNothing() {
        // a board through the light's centre stops every ray to the light's centre plane, but not before the sphere
        LightSampler lights = sphere(0.5);
        Box throughTheLight = new Box(new Vec3(0, 4, 0), new Vec3(5, 0.05, 5));

        assertFalse(lights.hiddenBy(0, throughTheLight, 0, 0, 0, probe));
        assertTrue(anySampleSeen(lights, throughTheLight, 0, 0, 0, 16));
    }

    @Test
    void anAreaLightIsHiddenOnlyWhenAllFourCornersAre() {
        LightSampler lights = area(2, 1);
        Box wide = new Box(new Vec3(0, 2, 0), new Vec3(2.5, 0.1, 2.5));
        // the same board moved so that the light's corners at +x peek past its edge
        Box shifted = new Box(new Vec3(-1.0, 2, -0.2), new Vec3(2.5, 0.1, 2.5));

        assertTrue(lights.hiddenBy(0, wide, 0, 0, 0, probe));
        assertFalse(anySampleSeen(lights, wide, 0, 0, 0, 64));
        assertFalse(lights.hiddenBy(0, shifted, 0, 0, 0, probe));
        assertTrue(anySampleSeen(lights, shifted, 0, 0, 0, 64));
    }

    @Test
    void whatItCallsHiddenIsHiddenFromEverySampleOfTheLight() {
        // random boards, boxes and balls near the edge of hiding either light from random points below
        Random random = new Random(46);
        int hidden = 0, told = 0;
        for (int round = 0; round < 3000; round++) {
            LightSampler lights = round % 2 == 0 ? sphere(0.2 + random.nextDouble()) : area(0.3 + 2 * random.nextDouble(), 0.2 + random.nextDouble());
            double px = random.nextDouble() - 0.5, py = random.nextDouble() - 0.5, pz = random.nextDouble() - 0.5;
            Vec3 at = new Vec3(2 * random.nextDouble() - 1, 1.2 + 1.5 * random.nextDouble(), 2 * random.nextDouble() - 1);
            Shape blocker = switch (round % 3) {
                case 0 -> new Box(at, new Vec3(0.5 + 2.5 * random.nextDouble(), 0.05 + random.nextDouble(), 0.5 + 2.5 * random.nextDouble()),
                        new Vec3(40 * random.nextDouble() - 20, 90 * random.nextDouble(), 40 * random.nextDouble() - 20));
                case 1 -> new Sphere(at, 0.3 + 1.2 * random.nextDouble());
                default -> new Box(at, new Vec3(0.3 + 1.5 * random.nextDouble(), 0.1, 0.3 + 1.5 * random.nextDouble()));
            };
            if (lights.hiddenBy(0, blocker, px, py, pz, probe)) {
                hidden++;
                if (anySampleSeen(lights, blocker, px, py, pz, 24)) {
                    fail("called hidden but a sample is seen: round " + round + ", " + blocker + " from " + px + ", " + py + ", " + pz);
                }
            } else if (!anySampleSeen(lights, blocker, px, py, pz, 24)) {
                told++; // hidden after all: a polygon around a sphere's cone reaches a little past it
            }
        }
        assertTrue(hidden > 300, "enough hidden cases to judge: " + hidden);
        assertTrue(told < hidden / 4, "few umbrae missed: " + told + " of " + (hidden + told));
    }
}

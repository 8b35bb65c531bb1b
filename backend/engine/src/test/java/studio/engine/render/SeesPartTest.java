package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Shape;
import studio.engine.geometry.TriangleMesh;
import studio.engine.light.AreaLight;
import studio.engine.light.LightSampler;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.mesh.MeshShapes;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/**
 * {@link ShadowRays#seesPart}: after a shadow ray from the floor to the centre of a 2 x 2 m area
 * light 4 m up was stopped, whether the point sees part of the light. A convex blocker answers by
 * the light's corners; a mesh is never asked.
 */
class SeesPartTest {

    private static boolean seesPart(Shape blocker, MaterialKind kind) {
        Scene scene = new Scene(new Camera(new Vec3(0, 1, 5), Vec3.ZERO, new Vec3(0, 1, 0), 40), List.of(
                new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)), MaterialDefaults.of(MaterialKind.CHALK, Rgb.WHITE)),
                new SceneObject(blocker, MaterialDefaults.of(kind, Rgb.WHITE))),
                List.of(new AreaLight(new Vec3(0, 4, 0), 2, 2, Vec3.ZERO, Rgb.WHITE, 1, false, false)), Rgb.BLACK, 0);
        LightSampler lights = new LightSampler(scene.lights());
        ShadowRays shadows = new ShadowRays(scene, RenderSettings.DEFAULT_MIN_PATH_WEIGHT);
        Hit floor = new Hit();
        floor.nx = floor.gx = 0;
        floor.ny = floor.gy = 1;
        floor.nz = floor.gz = 0;
        floor.ex = floor.ey = floor.ez = 1e-12;
        floor.primitive = 0;
        assertTrue(lights.sample(0, 0, 0, 0, 0.5, 0.5));
        assertFalse(shadows.reach(0, floor, lights.tx, lights.ty, lights.tz), "the ray to the light's centre is stopped");
        return shadows.seesPart(0, lights);
    }

    @Test
    void aBoardThatHidesAllOfTheLightMakesAnUmbra() {
        assertFalse(seesPart(new Box(new Vec3(0, 2, 0), new Vec3(3, 0.05, 3)), MaterialKind.CHALK));
    }

    @Test
    void aSmallerBoardLeavesAPenumbra() {
        assertTrue(seesPart(new Box(new Vec3(0, 2, 0), new Vec3(0.5, 0.05, 0.5)), MaterialKind.CHALK));
    }

    /**
     * The penumbra light the integrator finds at a floor point, from the light's centre, after a
     * first floor point's shadow ray: the ray before may leave a different blocker in the shadow
     * cache ({@link studio.engine.geometry.Ray#blocker}).
     */
    private static double penumbraAfter(Integrator integrator, double firstX, double x) {
        integrator.lightU = integrator.lightV = 0.5;
        integrator.watchPenumbrae = false;
        Radiance.of(integrator, new Ray(firstX, 0.5, 0, 0, -1, 0));
        integrator.watchPenumbrae = true;
        integrator.penumbraLight = 0;
        Radiance.of(integrator, new Ray(x, 0.5, 0, 0, -1, 0));
        return integrator.penumbraLight;
    }

    @Test
    void whatAPointSeesDoesNotDependOnTheRayBefore() {
        // an upper board (x up to 0.9, y = 3) hides the whole light from the origin; a lower strip
        // (y = 1, z within 0.1) stops the ray to the light's centre there too, but not the rays to its
        // corners. From x = 4 the ray to the centre meets only the strip, from x = -1 only the board.
        Scene scene = new Scene(new Camera(new Vec3(0, 1, 5), Vec3.ZERO, new Vec3(0, 1, 0), 40), List.of(
                new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)), MaterialDefaults.of(MaterialKind.CHALK, Rgb.WHITE)),
                new SceneObject(new Box(new Vec3(-2.1, 3, 0), new Vec3(6, 0.05, 6)), MaterialDefaults.of(MaterialKind.CHALK, Rgb.WHITE)),
                new SceneObject(new Box(new Vec3(1.6, 1, 0), new Vec3(3.8, 0.05, 0.2)), MaterialDefaults.of(MaterialKind.CHALK, Rgb.WHITE))),
                List.of(new AreaLight(new Vec3(0, 4, 0), 2, 2, Vec3.ZERO, Rgb.WHITE, 1, false, false)), Rgb.BLACK, 0);
        Integrator integrator = new Integrator(scene, 1, RenderSettings.DEFAULT_MIN_PATH_WEIGHT);

        double afterStrip = penumbraAfter(integrator, 4, 0), afterBoard = penumbraAfter(integrator, -1, 0);

        assertEquals(afterBoard, afterStrip, "the origin's penumbra light after a ray the strip stopped, and after one the board did");
    }

    @Test
    void aMeshIsNotAskedWhateverItHides() {
        TriangleMesh small = new TriangleMesh(MeshShapes.icosphere(2), new Vec3(0, 2, 0), 0.3, Vec3.ZERO);
        assertFalse(seesPart(small, MaterialKind.CHALK), "a penumbra, but a mesh's corners tell nothing");
    }
}

package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Plane;
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

    @Test
    void aMeshIsNotAskedWhateverItHides() {
        TriangleMesh small = new TriangleMesh(MeshShapes.icosphere(2), new Vec3(0, 2, 0), 0.3, Vec3.ZERO);
        assertFalse(seesPart(small, MaterialKind.CHALK), "a penumbra, but a mesh's corners tell nothing");
    }
}

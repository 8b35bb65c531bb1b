package studio.engine.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Shape;
import studio.engine.geometry.Sphere;
import studio.engine.math.Vec3;

class PlaneLeavesTest {

    private static Plane floorAt(double y) {
        return new Plane(new Vec3(0, y, 0), new Vec3(0, 1, 0));
    }

    @Test
    void nearestPlaneWinsAndReportsItsDeclarationIndex() {
        Shape[] shapes = {new Sphere(new Vec3(0, 0, 9), 1), floorAt(-3), floorAt(-1), floorAt(-2)};
        PlaneLeaves planes = new PlaneLeaves(shapes, new int[] {1, 2, 3});
        Ray down = new Ray(0, 0, 0, 0, -1, 0);
        Hit hit = new Hit();
        hit.primitive = ShapeLeaves.NONE;
        double cull = planes.nearest(0, planes.size(), down, 10, 10, hit);
        assertEquals(2, hit.primitive);
        assertEquals(1, hit.t, 1e-12);
        assertEquals(1 * (1 + ShapeLeaves.TIE), cull, 1e-15);
    }

    @Test
    void ofCoincidentPlanesTheFirstDeclaredWinsInAnyOrder() {
        Shape[] shapes = {floorAt(-1), floorAt(-1)};
        Ray down = new Ray(0, 0, 0, 0, -1, 0);
        for (int[] order : new int[][] {{0, 1}, {1, 0}}) {
            Hit hit = new Hit();
            hit.primitive = ShapeLeaves.NONE;
            new PlaneLeaves(shapes, order).nearest(0, 2, down, 10, 10, hit);
            assertEquals(0, hit.primitive);
        }
    }

    @Test
    void anyFindsAPlaneBeforeTheLimitAndNamesItTheBlocker() {
        Shape[] shapes = {floorAt(-5), floorAt(-1)};
        PlaneLeaves planes = new PlaneLeaves(shapes, new int[] {0, 1});
        Ray down = new Ray(0, 0, 0, 0, -1, 0);
        assertFalse(planes.any(0, 2, down, 0.5));
        assertTrue(planes.any(0, 2, down, 2));
        assertEquals(1, down.blocker);
        assertFalse(planes.any(0, 2, new Ray(0, 0, 0, 0, 1, 0), 100));
    }

    @Test
    void refusesAShapeThatIsNotAPlane() {
        Shape[] shapes = {new Sphere(new Vec3(0, 0, 0), 1)};
        assertThrows(IllegalArgumentException.class, () -> new PlaneLeaves(shapes, new int[] {0}));
    }
}

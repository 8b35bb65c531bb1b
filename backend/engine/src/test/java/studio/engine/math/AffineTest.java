package studio.engine.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class AffineTest {

    private static void assertVec(Vec3 expected, double x, double y, double z) {
        assertEquals(expected.x(), x, 1e-12);
        assertEquals(expected.y(), y, 1e-12);
        assertEquals(expected.z(), z, 1e-12);
    }

    @Test
    void trsScalesThenRotatesThenTranslates() {
        double s = Math.sqrt(0.5); // 90 degrees about y: x -> -z
        Affine a = Affine.trs(new Vec3(1, 2, 3), 0, s, 0, s, new Vec3(2, 3, 4));
        Vec3 p = a.applyToPoint(new Vec3(1, 1, 1));
        // scaled (2, 3, 4), rotated about y (x, z) -> (z, -x): (4, 3, -2), moved: (5, 5, 1)
        assertVec(new Vec3(5, 5, 1), p.x(), p.y(), p.z());
    }

    @Test
    void columnMajorMatrixMatchesItsTrs() {
        double[] c = {0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 2, 3, 1};
        double s = Math.sqrt(0.5);
        Affine a = Affine.fromColumnMajor(c);
        Affine b = Affine.trs(new Vec3(1, 2, 3), 0, s, 0, s, new Vec3(1, 1, 1));
        Vec3 p = a.applyToPoint(new Vec3(0.3, -0.7, 2)), q = b.applyToPoint(new Vec3(0.3, -0.7, 2));
        assertVec(p, q.x(), q.y(), q.z());
    }

    @Test
    void composesOuterAfterInner() {
        Affine parent = Affine.trs(new Vec3(10, 0, 0), 0, 0, 0, 1, new Vec3(2, 2, 2));
        Affine child = Affine.trs(new Vec3(0, 1, 0), 0, 0, 0, 1, new Vec3(1, 1, 1));
        Vec3 p = parent.times(child).applyToPoint(new Vec3(1, 0, 0));
        assertVec(new Vec3(12, 2, 0), p.x(), p.y(), p.z());
    }

    @Test
    void normalsStayPerpendicularUnderNonUniformScale() {
        // the plane x + y = 0 has normal (1, 1, 0); scaled by (2, 1, 1) it is x/2 + y = 0, normal (1, 2, 0)/sqrt5
        Affine a = Affine.trs(Vec3.ZERO, 0, 0, 0, 1, new Vec3(2, 1, 1));
        double[] n = new double[3];
        a.applyToNormals(new double[] {1, 1, 0}, 1, n, 0);
        assertVec(new Vec3(1, 2, 0).normalized(), n[0], n[1], n[2]);
    }

    @Test
    void mirroringKeepsNormalsOnTheirSide() {
        Affine a = Affine.trs(Vec3.ZERO, 0, 0, 0, 1, new Vec3(-1, 1, 1));
        double[] n = new double[3];
        a.applyToNormals(new double[] {1, 0, 0}, 1, n, 0);
        assertVec(new Vec3(-1, 0, 0), n[0], n[1], n[2]);
        assertEquals(-1, a.determinant(), 0);
    }

    @Test
    void refusesProjectionsAndNonFiniteValues() {
        double[] c = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0.5, 0, 0, 0, 1};
        assertThrows(IllegalArgumentException.class, () -> Affine.fromColumnMajor(c));
        double[] nan = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, Double.NaN, 0, 0, 1};
        assertThrows(IllegalArgumentException.class, () -> Affine.fromColumnMajor(nan));
        assertThrows(IllegalArgumentException.class, () -> Affine.trs(Vec3.ZERO, 0, 0, 0, 0, new Vec3(1, 1, 1)));
    }
}

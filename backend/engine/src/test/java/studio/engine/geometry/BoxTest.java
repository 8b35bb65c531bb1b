package studio.engine.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static studio.engine.geometry.GeometryAssertions.assertSentinel;
import static studio.engine.geometry.GeometryAssertions.assertVec;
import static studio.engine.geometry.GeometryAssertions.randomUnit;
import static studio.engine.geometry.GeometryAssertions.sentinelHit;
import static studio.engine.geometry.GeometryAssertions.uniform;

import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.math.Rotation;
import studio.engine.math.Vec3;

class BoxTest {

    private static final double EPS = 1e-12;
    private static final double HALF_SQRT2 = Math.sqrt(0.5);

    @Test
    void boxHitOnEachFaceReportsDistancePointAndOutwardNormal() {
        // Box [-1,1] x [-2,2] x [-3,3]; from 10 units out along each axis, straight in.
        Box box = new Box(Vec3.ZERO, new Vec3(2, 4, 6));
        double[] half = {1, 2, 3};
        for (int axis = 0; axis < 3; axis++) {
            for (int sign = -1; sign <= 1; sign += 2) {
                double[] o = {0.25, -0.5, 0.75};
                double[] d = {0, 0, 0};
                o[axis] = sign * 10;
                d[axis] = -sign;
                Hit hit = new Hit();

                assertTrue(box.intersect(new Ray(o[0], o[1], o[2], d[0], d[1], d[2]), Double.POSITIVE_INFINITY, hit));

                double[] p = o.clone();
                p[axis] = sign * half[axis];
                double[] n = {0, 0, 0};
                n[axis] = sign;
                assertEquals(10 - half[axis], hit.t, 0.0);
                assertVec(new Vec3(p[0], p[1], p[2]), hit.point(), 0.0);
                assertVec(new Vec3(n[0], n[1], n[2]), hit.normal(), 0.0);
            }
        }
    }

    @Test
    void boxOffCentreHitIsRelativeToItsCentre() {
        Box box = new Box(new Vec3(10, -5, 2), new Vec3(2, 2, 2));
        Hit hit = new Hit();

        assertTrue(box.intersect(new Ray(10.5, 0, 2.5, 0, -2, 0), Double.POSITIVE_INFINITY, hit));

        assertEquals(2.0, hit.t, EPS); // y from 0 down to -4 at speed 2
        assertVec(new Vec3(10.5, -4, 2.5), hit.point(), EPS);
        assertVec(new Vec3(0, 1, 0), hit.normal(), 0.0);
    }

    @Test
    void boxRotated45DegreesAboutYIsHitOnItsRotatedFace() {
        // The cube [-1,1]^3 turned 45 degrees about y: its local +z face has normal (s, 0, s), s = sqrt(1/2),
        // and lies on x + z = sqrt(2). The ray z = 0.2 along -x meets it at x = sqrt(2) - 0.2.
        Box box = new Box(Vec3.ZERO, new Vec3(2, 2, 2), new Vec3(0, 45, 0));
        Hit hit = new Hit();

        assertTrue(box.intersect(new Ray(5, 0, 0.2, -1, 0, 0), Double.POSITIVE_INFINITY, hit));

        assertEquals(5.2 - Math.sqrt(2), hit.t, EPS);
        assertVec(new Vec3(Math.sqrt(2) - 0.2, 0, 0.2), hit.point(), EPS);
        assertVec(new Vec3(HALF_SQRT2, 0, HALF_SQRT2), hit.normal(), EPS);
        assertEquals(1.0, hit.normal().length(), EPS);
    }

    @Test
    void boxRotated45DegreesAboutYIsHitHeadOnAlongItsLocalXAxis() {
        // Local +x in world is (s, 0, -s); a ray along -(s,0,-s) from 5 units out meets that face at t = 4.
        Box box = new Box(Vec3.ZERO, new Vec3(2, 2, 2), new Vec3(0, 45, 0));
        Hit hit = new Hit();

        assertTrue(box.intersect(new Ray(5 * HALF_SQRT2, 0, -5 * HALF_SQRT2, -HALF_SQRT2, 0, HALF_SQRT2),
                Double.POSITIVE_INFINITY, hit));

        assertEquals(4.0, hit.t, EPS);
        assertVec(new Vec3(HALF_SQRT2, 0, -HALF_SQRT2), hit.point(), EPS);
        assertVec(new Vec3(HALF_SQRT2, 0, -HALF_SQRT2), hit.normal(), EPS);
    }

    @Test
    void boxRotated90DegreesAboutXTurnsItsHeightIntoDepth() {
        // Rx(90) maps local y to world z and local z to world -y: size (2,4,6) spans y in [-3,3], z in [-2,2].
        Box box = new Box(Vec3.ZERO, new Vec3(2, 4, 6), new Vec3(90, 0, 0));
        Hit hit = new Hit();

        assertTrue(box.intersect(new Ray(0, 10, 0, 0, -1, 0), Double.POSITIVE_INFINITY, hit));
        assertEquals(7.0, hit.t, EPS);
        assertVec(new Vec3(0, 1, 0), hit.normal(), EPS);

        assertTrue(box.intersect(new Ray(0, 0, 10, 0, 0, -1), Double.POSITIVE_INFINITY, hit));
        assertEquals(8.0, hit.t, EPS);
        assertVec(new Vec3(0, 0, 1), hit.normal(), EPS);
    }

    @Test
    void rotatedBoxIsHitExactlyAtTheSurfacePointARayIsAimedAt() {
        Vec3 center = new Vec3(1, -2, 0.5), size = new Vec3(2, 1, 3), degrees = new Vec3(30, 45, 60);
        Box box = new Box(center, size, degrees);
        Rotation rotation = Rotation.fromEulerDegrees(degrees);
        Random random = new Random(11);
        Hit hit = new Hit();
        for (int i = 0; i < 5_000; i++) {
            int axis = random.nextInt(3);
            double sign = random.nextBoolean() ? 1 : -1;
            double[] local = {uniform(random, -0.9, 0.9) * size.x() / 2, uniform(random, -0.9, 0.9) * size.y() / 2,
                    uniform(random, -0.9, 0.9) * size.z() / 2};
            local[axis] = sign * size.get(axis) / 2;
            double[] localNormal = {0, 0, 0};
            localNormal[axis] = sign;
            Vec3 p = center.plus(rotation.apply(new Vec3(local[0], local[1], local[2])));
            Vec3 n = rotation.apply(new Vec3(localNormal[0], localNormal[1], localNormal[2]));
            Vec3 d = randomUnit(random);
            if (d.dot(n) > -0.05) {
                d = d.minus(n.times(d.dot(n) + 0.5)).normalized(); // make it enter through this face
            }
            Vec3 o = p.minus(d.times(uniform(random, 0.5, 20)));

            assertTrue(box.intersect(new Ray(o, d), Double.POSITIVE_INFINITY, hit), "ray towards " + p);

            assertVec(p, hit.point(), EPS);
            assertVec(n, hit.normal(), EPS);
            assertEquals(p.minus(o).length(), hit.t, EPS);
        }
    }

    @Test
    void boxMissLeavesHitUntouched() {
        Box box = new Box(Vec3.ZERO, new Vec3(2, 2, 2), new Vec3(0, 45, 0));
        Hit hit = sentinelHit();

        assertFalse(box.intersect(new Ray(5, 1.0001, 0, -1, 0, 0), Double.POSITIVE_INFINITY, hit), "above the top");
        assertFalse(box.intersect(new Ray(5, 0, 0, 1, 0, 0), Double.POSITIVE_INFINITY, hit), "box behind");
        // In the plane y = 0 the turned cube is the diamond |x| + |z| <= sqrt(2); the line z = 1.42 passes outside.
        assertFalse(box.intersect(new Ray(5, 0, 1.42, -1, 0, 0), Double.POSITIVE_INFINITY, hit));

        assertSentinel(hit);
    }

    @Test
    void boxHitFromInsideReportsExitWithNormalAlongTheRay() {
        Box box = new Box(new Vec3(1, 1, 1), new Vec3(2, 4, 6));
        Hit hit = new Hit();

        assertTrue(box.intersect(new Ray(1, 1, 1, 0, 0, -1), Double.POSITIVE_INFINITY, hit));

        assertEquals(3.0, hit.t, EPS);
        assertVec(new Vec3(1, 1, -2), hit.point(), EPS);
        assertVec(new Vec3(0, 0, -1), hit.normal(), 0.0);
    }

    @Test
    void rotatedBoxHitFromInsideReportsExitWithNormalAlongTheRay() {
        Box box = new Box(Vec3.ZERO, new Vec3(2, 2, 2), new Vec3(0, 45, 0));
        Hit hit = new Hit();

        assertTrue(box.intersect(new Ray(0, 0, 0, -HALF_SQRT2, 0, -HALF_SQRT2), Double.POSITIVE_INFINITY, hit));

        assertEquals(1.0, hit.t, EPS);
        assertVec(new Vec3(-HALF_SQRT2, 0, -HALF_SQRT2), hit.normal(), EPS);
    }

    @Test
    void boxRayAlongAnEdgeHitsTheClosedBox() {
        Box box = new Box(Vec3.ZERO, new Vec3(2, 2, 2));
        Hit hit = new Hit();

        assertTrue(box.intersect(new Ray(1, 1, 5, 0, 0, -1), Double.POSITIVE_INFINITY, hit));

        assertEquals(4.0, hit.t, 0.0);
        assertVec(new Vec3(1, 1, 1), hit.point(), 0.0);
        assertTrue(hit.normal().isFinite());
        assertEquals(1.0, hit.normal().length(), EPS);
        assertTrue(hit.normal().dot(new Vec3(0, 0, -1)) <= 0, "normal faces the incoming ray");
    }

    @Test
    void boxRespectsTMaxAsAnExclusiveLimit() {
        Box box = new Box(Vec3.ZERO, new Vec3(2, 2, 2));
        Ray ray = new Ray(0, 0, 5, 0, 0, -1); // enters at 4, leaves at 6
        Hit hit = sentinelHit();

        assertFalse(box.intersect(ray, 4.0, hit));
        assertFalse(box.intersect(ray, 3.0, hit));
        assertFalse(box.occluded(ray, 4.0));
        assertSentinel(hit);
        assertTrue(box.intersect(ray, Math.nextUp(4.0), hit));
        assertEquals(4.0, hit.t, 0.0);
    }

    @Test
    void boxOccludedAgreesWithIntersect() {
        Random random = new Random(5);
        Box[] boxes = {new Box(new Vec3(0.2, 0.1, -0.3), new Vec3(1, 2, 1.5)),
                new Box(new Vec3(0.2, 0.1, -0.3), new Vec3(1, 2, 1.5), new Vec3(0, 45, 0)),
                new Box(new Vec3(-0.4, 0.3, 0.2), new Vec3(2, 0.5, 1), new Vec3(30, -20, 75))};
        Hit hit = new Hit();
        for (Box box : boxes) {
            int hits = 0;
            for (int i = 0; i < 20_000; i++) {
                double[] o = {uniform(random, -3, 3), uniform(random, -3, 3), uniform(random, -3, 3)};
                double[] d = new double[3];
                for (int k = 0; k < 3; k++) { // aimed near the box
                    d[k] = uniform(random, -1.2, 1.2) - o[k];
                }
                if (random.nextInt(5) == 0) {
                    d[random.nextInt(3)] = 0; // axis-parallel components exercise the d == 0 branch
                }
                Ray ray = new Ray(o[0], o[1], o[2], d[0], d[1], d[2]);
                double tMax = random.nextInt(4) == 0 ? Double.POSITIVE_INFINITY : uniform(random, 0, 5);
                boolean intersects = box.intersect(ray, tMax, hit);
                assertEquals(intersects, box.occluded(ray, tMax), box + " " + ray + " tMax=" + tMax);
                if (intersects) {
                    hits++;
                    assertTrue(hit.t > 0 && hit.t < tMax);
                }
            }
            assertTrue(hits > 2000, "the sample should contain hits: " + hits);
        }
    }

    /**
     * An unrotated box takes rays as they are, without turning them into its frame: the same
     * numbers as turning them, which a box turned half a turn about any axis does (its matrix is
     * exact, its set of points the same, and every product a sign change).
     */
    @Test
    void unrotatedBoxHitsAsTheSameBoxTurnedHalfATurn() {
        Random random = new Random(11);
        Vec3 center = new Vec3(0.2, 0.1, -0.3), size = new Vec3(1, 2, 1.5);
        Box unrotated = new Box(center, size);
        Box[] turned = {new Box(center, size, new Vec3(180, 0, 0)), new Box(center, size, new Vec3(0, 180, 0)),
                new Box(center, size, new Vec3(0, 0, 180))};
        Hit expected = new Hit(), actual = new Hit();
        int hits = 0;
        for (int i = 0; i < 20_000; i++) {
            double[] o = {uniform(random, -3, 3), uniform(random, -3, 3), uniform(random, -3, 3)};
            double[] d = new double[3];
            for (int k = 0; k < 3; k++) {
                d[k] = uniform(random, -1.2, 1.2) - o[k];
            }
            if (random.nextInt(5) == 0) {
                d[random.nextInt(3)] = 0;
            }
            Ray ray = new Ray(o[0], o[1], o[2], d[0], d[1], d[2]);
            double tMax = random.nextInt(4) == 0 ? Double.POSITIVE_INFINITY : uniform(random, 0, 5);
            boolean intersects = unrotated.intersect(ray, tMax, actual);
            hits += intersects ? 1 : 0;
            for (Box box : turned) {
                String what = box + " " + ray + " tMax=" + tMax;
                assertEquals(box.intersect(ray, tMax, expected), intersects, what);
                assertEquals(box.occluded(ray, tMax), unrotated.occluded(ray, tMax), what);
                if (intersects) {
                    assertEquals(expected.t, actual.t, 0.0, what);
                    assertEquals(expected.px, actual.px, 0.0, what);
                    assertEquals(expected.py, actual.py, 0.0, what);
                    assertEquals(expected.pz, actual.pz, 0.0, what);
                    assertEquals(expected.nx, actual.nx, 0.0, what);
                    assertEquals(expected.ny, actual.ny, 0.0, what);
                    assertEquals(expected.nz, actual.nz, 0.0, what);
                }
            }
        }
        assertTrue(hits > 2000, "the sample should contain hits: " + hits);
    }

    @Test
    void boxRejectsZeroNegativeAndNonFiniteSize() {
        assertThrows(IllegalArgumentException.class, () -> new Box(Vec3.ZERO, Vec3.ZERO));
        assertThrows(IllegalArgumentException.class, () -> new Box(Vec3.ZERO, new Vec3(1, 0, 1)));
        assertThrows(IllegalArgumentException.class, () -> new Box(Vec3.ZERO, new Vec3(1, 1, -1)));
        assertThrows(IllegalArgumentException.class, () -> new Box(Vec3.ZERO, new Vec3(1, Double.NaN, 1)));
        assertThrows(IllegalArgumentException.class,
                () -> new Box(Vec3.ZERO, new Vec3(1, 1, 1), new Vec3(0, Double.POSITIVE_INFINITY, 0)));
    }
}

package studio.engine.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static studio.engine.geometry.GeometryAssertions.assertSentinel;
import static studio.engine.geometry.GeometryAssertions.assertVec;
import static studio.engine.geometry.GeometryAssertions.sentinelHit;
import static studio.engine.geometry.GeometryAssertions.uniform;

import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.math.Vec3;

class SphereTest {

    private static final double EPS = 1e-12;

    @Test
    void sphereHitFromOutsideReportsNearestRootPointAndOutwardNormal() {
        Sphere sphere = new Sphere(new Vec3(1, 2, 3), 2);
        Hit hit = new Hit();

        assertTrue(sphere.intersect(new Ray(1, 2, 10, 0, 0, -1), Double.POSITIVE_INFINITY, hit));

        assertEquals(5.0, hit.t, 0.0);
        assertVec(new Vec3(1, 2, 5), hit.point(), 0.0);
        assertVec(new Vec3(0, 0, 1), hit.normal(), 0.0);
    }

    @Test
    void sphereObliqueHitLandsOnTheSurfaceWithRadialNormal() {
        // Ray y=3 along +x meets x^2+y^2=25 at x=-4: t=6, p=(-4,3,0), n=(-0.8,0.6,0).
        Sphere sphere = new Sphere(Vec3.ZERO, 5);
        Hit hit = new Hit();

        assertTrue(sphere.intersect(new Ray(-10, 3, 0, 1, 0, 0), Double.POSITIVE_INFINITY, hit));

        assertEquals(6.0, hit.t, EPS);
        assertVec(new Vec3(-4, 3, 0), hit.point(), EPS);
        assertVec(new Vec3(-0.8, 0.6, 0), hit.normal(), EPS);
        assertEquals(1.0, hit.normal().length(), EPS);
    }

    @Test
    void sphereHitDistanceIsInUnitsOfTheRayDirection() {
        Sphere sphere = new Sphere(new Vec3(1, 2, 3), 2);
        Hit hit = new Hit();

        assertTrue(sphere.intersect(new Ray(1, 2, 10, 0, 0, -2), Double.POSITIVE_INFINITY, hit));

        assertEquals(2.5, hit.t, EPS);
        assertVec(new Vec3(1, 2, 5), hit.point(), EPS);
        assertVec(new Vec3(0, 0, 1), hit.normal(), EPS);
    }

    @Test
    void sphereMissLeavesHitUntouched() {
        Sphere sphere = new Sphere(Vec3.ZERO, 5);
        Hit hit = sentinelHit();

        assertFalse(sphere.intersect(new Ray(-10, 5.000001, 0, 1, 0, 0), Double.POSITIVE_INFINITY, hit));
        assertFalse(sphere.intersect(new Ray(-10, 0, 0, -1, 0, 0), Double.POSITIVE_INFINITY, hit),
                "sphere behind the ray");

        assertSentinel(hit);
    }

    @Test
    void sphereHitFromInsideReportsExitWithNormalAlongTheRay() {
        Sphere sphere = new Sphere(new Vec3(1, 1, 1), 3);
        Hit hit = new Hit();

        assertTrue(sphere.intersect(new Ray(1, 1, 1, 0, -1, 0), Double.POSITIVE_INFINITY, hit));

        assertEquals(3.0, hit.t, EPS);
        assertVec(new Vec3(1, -2, 1), hit.point(), EPS);
        assertVec(new Vec3(0, -1, 0), hit.normal(), EPS);
    }

    @Test
    void sphereHitFromOffCentreInsidePointReportsFarRoot() {
        // From (0,0,3) inside r=5 along +x: exit at x=4, t=4, n=(0.8,0,0.6).
        Sphere sphere = new Sphere(Vec3.ZERO, 5);
        Hit hit = new Hit();

        assertTrue(sphere.intersect(new Ray(0, 0, 3, 1, 0, 0), Double.POSITIVE_INFINITY, hit));

        assertEquals(4.0, hit.t, EPS);
        assertVec(new Vec3(0.8, 0, 0.6), hit.normal(), EPS);
        assertTrue(hit.normal().dot(new Vec3(1, 0, 0)) > 0, "exit normal points along the ray");
    }

    @Test
    void sphereTangentRayEitherMissesOrTouchesAtTheTangentPoint() {
        // disc is exactly 0 here (robustness case NUM-03 b)
        Sphere sphere = new Sphere(new Vec3(0, 0, -5), 1);
        Hit hit = new Hit();

        if (sphere.intersect(new Ray(0, 1, 0, 0, 0, -1), Double.POSITIVE_INFINITY, hit)) {
            assertEquals(5.0, hit.t, EPS);
            assertVec(new Vec3(0, 1, 0), hit.normal(), EPS);
        }
        assertFalse(sphere.intersect(new Ray(0, 1 + 1e-9, 0, 0, 0, -1), Double.POSITIVE_INFINITY, new Hit()));
        assertTrue(sphere.intersect(new Ray(0, 1 - 1e-9, 0, 0, 0, -1), Double.POSITIVE_INFINITY, new Hit()));
    }

    @Test
    void sphereRespectsTMaxAsAnExclusiveLimit() {
        Sphere sphere = new Sphere(new Vec3(1, 2, 3), 2);
        Ray ray = new Ray(1, 2, 10, 0, 0, -1); // roots at 5 and 9
        Hit hit = sentinelHit();

        assertFalse(sphere.intersect(ray, 5.0, hit), "t == tMax is outside");
        assertFalse(sphere.intersect(ray, 4.0, hit));
        assertFalse(sphere.occluded(ray, 5.0));
        assertSentinel(hit);
        assertTrue(sphere.intersect(ray, Math.nextUp(5.0), hit));
        assertEquals(5.0, hit.t, 0.0);
    }

    @Test
    void sphereOccludedAgreesWithIntersect() {
        Random random = new Random(7);
        Sphere sphere = new Sphere(new Vec3(0.3, -0.2, 0.1), 1.3);
        Hit hit = new Hit();
        int hits = 0;
        for (int i = 0; i < 20_000; i++) {
            Ray ray = new Ray(uniform(random, -3, 3), uniform(random, -3, 3), uniform(random, -3, 3),
                    uniform(random, -1, 1), uniform(random, -1, 1), uniform(random, -1, 1));
            double tMax = random.nextInt(4) == 0 ? Double.POSITIVE_INFINITY : uniform(random, 0, 5);
            boolean intersects = sphere.intersect(ray, tMax, hit);
            assertEquals(intersects, sphere.occluded(ray, tMax), ray + " tMax=" + tMax);
            if (intersects) {
                hits++;
                assertTrue(hit.t > 0 && hit.t < tMax);
            }
        }
        assertTrue(hits > 1000, "the sample should contain hits: " + hits);
    }

    @Test
    void sphereRejectsZeroNegativeAndNonFiniteRadius() {
        assertThrows(IllegalArgumentException.class, () -> new Sphere(Vec3.ZERO, 0));
        assertThrows(IllegalArgumentException.class, () -> new Sphere(Vec3.ZERO, -1));
        assertThrows(IllegalArgumentException.class, () -> new Sphere(Vec3.ZERO, Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> new Sphere(Vec3.ZERO, Double.POSITIVE_INFINITY));
        assertThrows(IllegalArgumentException.class, () -> new Sphere(new Vec3(Double.NaN, 0, 0), 1));
    }
}

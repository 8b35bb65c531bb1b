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

class PlaneTest {

    private static final double EPS = 1e-12;

    @Test
    void planeHitReportsDistancePointAndItsUnitNormal() {
        Plane plane = new Plane(new Vec3(0, 2, 0), new Vec3(0, 3, 0)); // normal given unnormalised
        Hit hit = new Hit();

        assertTrue(plane.intersect(new Ray(1, 5, 1, 0, -1, 0), Double.POSITIVE_INFINITY, hit));

        assertEquals(3.0, hit.t, 0.0);
        assertVec(new Vec3(1, 2, 1), hit.point(), 0.0);
        assertVec(new Vec3(0, 1, 0), hit.normal(), 0.0);
    }

    @Test
    void tiltedPlaneObliqueHitLandsOnThePlane() {
        // Plane x + y = 0; from (2,2,1) along -(1,1,0)/|.| the hit is (0,0,1) at t = 2*sqrt(2).
        Plane plane = new Plane(Vec3.ZERO, new Vec3(1, 1, 0));
        Hit hit = new Hit();
        double s = Math.sqrt(0.5);

        assertTrue(plane.intersect(new Ray(2, 2, 1, -s, -s, 0), Double.POSITIVE_INFINITY, hit));

        assertEquals(2 * Math.sqrt(2), hit.t, EPS);
        assertVec(new Vec3(0, 0, 1), hit.point(), EPS);
        assertVec(new Vec3(s, s, 0), hit.normal(), EPS);
    }

    @Test
    void planeHitFromBehindKeepsItsDeclaredNormal() {
        Plane plane = new Plane(Vec3.ZERO, new Vec3(0, 1, 0));
        Hit hit = new Hit();

        assertTrue(plane.intersect(new Ray(0, -4, 0, 0, 2, 0), Double.POSITIVE_INFINITY, hit));

        assertEquals(2.0, hit.t, 0.0);
        assertVec(new Vec3(0, 1, 0), hit.normal(), 0.0);
    }

    @Test
    void planeMissLeavesHitUntouched() {
        Plane plane = new Plane(Vec3.ZERO, new Vec3(0, 1, 0));
        Hit hit = sentinelHit();

        assertFalse(plane.intersect(new Ray(0, 1, 0, 0, 1, 0), Double.POSITIVE_INFINITY, hit), "pointing away");
        assertFalse(plane.intersect(new Ray(0, 1, 0, 1, 0, 0), Double.POSITIVE_INFINITY, hit), "parallel");
        assertFalse(plane.intersect(new Ray(0, 0, 0, 1, 0, 0), Double.POSITIVE_INFINITY, hit), "in the plane");

        assertSentinel(hit);
    }

    @Test
    void planeRespectsTMaxAsAnExclusiveLimit() {
        Plane plane = new Plane(Vec3.ZERO, new Vec3(0, 1, 0));
        Ray ray = new Ray(0, 3, 0, 0, -1, 0);
        Hit hit = sentinelHit();

        assertFalse(plane.intersect(ray, 3.0, hit));
        assertFalse(plane.occluded(ray, 3.0));
        assertSentinel(hit);
        assertTrue(plane.intersect(ray, Math.nextUp(3.0), hit));
        assertEquals(3.0, hit.t, 0.0);
    }

    @Test
    void planeOccludedAgreesWithIntersect() {
        Random random = new Random(3);
        Plane plane = new Plane(new Vec3(0.1, -0.2, 0.3), new Vec3(0.3, 1, -0.4));
        Hit hit = new Hit();
        int hits = 0;
        for (int i = 0; i < 20_000; i++) {
            Ray ray = new Ray(uniform(random, -3, 3), uniform(random, -3, 3), uniform(random, -3, 3),
                    uniform(random, -1, 1), uniform(random, -1, 1), uniform(random, -1, 1));
            double tMax = random.nextInt(4) == 0 ? Double.POSITIVE_INFINITY : uniform(random, 0, 5);
            boolean intersects = plane.intersect(ray, tMax, hit);
            assertEquals(intersects, plane.occluded(ray, tMax), ray + " tMax=" + tMax);
            if (intersects) {
                hits++;
                assertTrue(hit.t > 0 && hit.t < tMax);
            }
        }
        assertTrue(hits > 1000, "the sample should contain hits: " + hits);
    }

    @Test
    void planeRejectsZeroAndNonFiniteNormal() {
        assertThrows(IllegalArgumentException.class, () -> new Plane(Vec3.ZERO, Vec3.ZERO));
        assertThrows(IllegalArgumentException.class, () -> new Plane(Vec3.ZERO, new Vec3(0, Double.NaN, 0)));
        assertThrows(IllegalArgumentException.class, () -> new Plane(new Vec3(Double.POSITIVE_INFINITY, 0, 0),
                new Vec3(0, 1, 0)));
    }
}

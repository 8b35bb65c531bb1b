package studio.engine.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import studio.engine.math.Vec3;

/** Shared helpers of the geometry tests: vector comparison and a hit record with recognisable contents. */
final class GeometryAssertions {

    private GeometryAssertions() {
    }

    static double uniform(Random random, double lo, double hi) {
        return lo + (hi - lo) * random.nextDouble();
    }

    /** A uniformly distributed unit vector. */
    static Vec3 randomUnit(Random random) {
        double z = uniform(random, -1, 1), phi = uniform(random, 0, 2 * Math.PI);
        double r = Math.sqrt(1 - z * z);
        return new Vec3(r * Math.cos(phi), r * Math.sin(phi), z);
    }

    /** A hit record filled with values no intersection produces, to show it was left alone. */
    static Hit sentinelHit() {
        Hit hit = new Hit();
        hit.set(-42, 1, 2, 3, 4, 5, 6, 7, 8, 9);
        hit.primitive = 99;
        return hit;
    }

    static void assertSentinel(Hit hit) {
        assertEquals(-42, hit.t, 0.0);
        assertVec(new Vec3(1, 2, 3), hit.point(), 0.0);
        assertVec(new Vec3(4, 5, 6), hit.normal(), 0.0);
        assertEquals(7, hit.ex, 0.0);
        assertEquals(8, hit.ey, 0.0);
        assertEquals(9, hit.ez, 0.0);
        assertEquals(99, hit.primitive);
    }

    static void assertVec(Vec3 expected, Vec3 actual, double tolerance) {
        assertTrue(Math.abs(expected.x() - actual.x()) <= tolerance
                        && Math.abs(expected.y() - actual.y()) <= tolerance
                        && Math.abs(expected.z() - actual.z()) <= tolerance,
                () -> "expected " + expected + " but was " + actual + " (tolerance " + tolerance + ")");
    }
}

package studio.engine.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

/** Robustness case NUM-06: the BVH's ray/box test keeps flat boxes and rays that only touch an edge. */
class SlabTest {

    private static boolean hits(double[] box, double ox, double oy, double oz, double dx, double dy, double dz,
                                double tMax) {
        return Slab.hits(box, 0, ox, oy, oz, 1 / dx, 1 / dy, 1 / dz, tMax);
    }

    /** The naive test NUM-06 warns about: strict tNear &lt; tFar, no widening. */
    private static boolean strictHits(double[] box, double ox, double oy, double oz, double dx, double dy, double dz) {
        return naiveHits(box, ox, oy, oz, dx, dy, dz, true);
    }

    /** Min/max slab test without widening, strict or not. */
    private static boolean naiveHits(double[] box, double ox, double oy, double oz, double dx, double dy, double dz,
                                     boolean strict) {
        double tNear = 0, tFar = Double.POSITIVE_INFINITY;
        double[] o = {ox, oy, oz}, d = {dx, dy, dz};
        for (int a = 0; a < 3; a++) {
            double t0 = (box[a] - o[a]) / d[a], t1 = (box[a + 3] - o[a]) / d[a];
            tNear = Math.max(tNear, Math.min(t0, t1));
            tFar = Math.min(tFar, Math.max(t0, t1));
        }
        return strict ? tNear < tFar : tNear <= tFar;
    }

    @Test
    @DisplayName("NUM-06a: a triangle's flat box (zmin = zmax) is not culled, where a strict tNear < tFar culls all 441 rays")
    void flatBoxOfATriangleNum06aKeepsAll441RaysThatAStrictCompareLoses() {
        double[] box = {-1, -1, -5, 1, 1, -5};
        int robust = 0, strict = 0;
        for (int i = 0; i <= 20; i++) {
            for (int j = 0; j <= 20; j++) {
                double a = -0.15 + 0.015 * i, b = -0.15 + 0.015 * j;
                robust += hits(box, 0, 0, 0, a, b, -1, Double.POSITIVE_INFINITY) ? 1 : 0;
                strict += strictHits(box, 0, 0, 0, a, b, -1) ? 1 : 0;
            }
        }
        assertEquals(441, robust, "rays kept by the robust test");
        assertEquals(0, strict, "the failure mode: the strict test drops the whole flat box");
    }

    @Test
    @DisplayName("NUM-06b: rays touching a box only along an edge are kept (>= 99.99 %); unwidened tests lose 6.6 %")
    void raysTouchingOnlyAnEdgeNum06bAreKeptDespiteRounding() {
        double[] box = {-0.37, 0.21, -1.13, 0.61, 1.07, -0.29};
        Random random = new Random(6);
        int rays = 20_000, rejected = 0, rejectedUnwidened = 0;
        for (int i = 0; i < rays; i++) {
            double pz = uniform(random, box[2], box[5]);
            double a = uniform(random, 0.2, 1), b = uniform(random, 0.2, 1), c = uniform(random, -0.3, 0.3);
            double len = Math.sqrt(a * a + b * b + c * c);
            double dx = a / len, dy = -b / len, dz = c / len;
            double s = uniform(random, 0.5, 50);
            double ox = 0.61 - s * dx, oy = 1.07 - s * dy, oz = pz - s * dz;
            if (!hits(box, ox, oy, oz, dx, dy, dz, Double.POSITIVE_INFINITY)) {
                rejected++;
            }
            if (!naiveHits(box, ox, oy, oz, dx, dy, dz, false)) {
                rejectedUnwidened++;
            }
        }
        assertTrue(rejected <= rays / 10_000, "rejected " + rejected + " of " + rays + " edge-touching rays");
        assertTrue(rejectedUnwidened > rays / 20, "the failure mode without widening: " + rejectedUnwidened);
    }

    @Test
    @DisplayName("NUM-06: zero direction components give no 0*inf NaN: a ray parallel to a slab is in or out, faces count as in")
    void zeroDirectionComponentsAreDecidedByTheOriginAlone() {
        double[] box = {0, 0, 0, 1, 1, 1};
        // Parallel to x, y slabs; the origin inside, on a face (0*inf = NaN), on an edge, outside.
        assertTrue(hits(box, 0.5, 0.5, -1, 0, 0, 1, Double.POSITIVE_INFINITY));
        assertTrue(hits(box, 0, 0.5, -1, 0, 0, 1, Double.POSITIVE_INFINITY));
        assertTrue(hits(box, 1, 1, -1, 0, 0, 1, Double.POSITIVE_INFINITY));
        assertTrue(hits(box, 1, 1, -1, -0.0, -0.0, 1, Double.POSITIVE_INFINITY));
        assertFalse(hits(box, Math.nextUp(1.0), 0.5, -1, 0, 0, 1, Double.POSITIVE_INFINITY));
        assertFalse(hits(box, 0.5, -1e-300, -1, 0, -0.0, 1, Double.POSITIVE_INFINITY));
        // A flat box lying in the plane of a parallel ray.
        assertTrue(hits(new double[] {0, 0, 0, 1, 0, 1}, -1, 0, 0.5, 1, 0, 0, Double.POSITIVE_INFINITY));
    }

    @Test
    void boxBehindTheOriginOrBeyondTMaxIsCulledAndABoxAroundTheOriginIsNot() {
        double[] box = {-1, -1, -1, 1, 1, 1};
        assertFalse(hits(box, 0, 0, 5, 0, 0, 1, Double.POSITIVE_INFINITY), "behind");
        assertFalse(hits(box, 0, 0, 5, 0, 0, -1, 3.9), "beyond tMax");
        assertTrue(hits(box, 0, 0, 5, 0, 0, -1, 4), "entry exactly at tMax is kept (non-strict)");
        assertTrue(hits(box, 0.2, 0.3, 0.4, 0.3, -0.5, 0.1, 1e-9), "origin inside");
    }

    private static double uniform(Random random, double lo, double hi) {
        return lo + (hi - lo) * random.nextDouble();
    }

    @Test
    @DisplayName("entry: the distance where the ray enters (0 inside), NaN on a miss even with an infinite tMax, "
            + "and on 100,000 random rays the entry of a min/max slab test with the same widening")
    void entryGivesTheEntryDistanceOrNaN() {
        double[] box = {-1, -1, -1, 1, 1, 1};
        double inf = Double.POSITIVE_INFINITY;
        assertEquals(4, Slab.entry(box, 0, 0, 0, 5, 1 / 0.0, 1 / 0.0, -1, inf));
        assertEquals(0, Slab.entry(box, 0, 0, 0, 0, 1, 1, 1, inf));
        assertTrue(Double.isNaN(Slab.entry(box, 0, 0, 3, 5, 1 / 0.0, 1 / 0.0, -1, inf)), "passes above the box");
        assertTrue(Double.isNaN(Slab.entry(box, 0, 0, 0, 5, 1 / 0.0, 1 / 0.0, -1, 3.9)), "box beyond tMax");
        assertFalse(Slab.hits(box, 0, 0, 3, 5, 1 / 0.0, 1 / 0.0, -1, inf));
        assertTrue(Slab.hits(box, 0, 0, 0, 5, 1 / 0.0, 1 / 0.0, -1, inf));
        Random random = new Random(7);
        int hits = 0;
        for (int i = 0; i < 100_000; i++) {
            double[] o = {4 * random.nextGaussian(), 4 * random.nextGaussian(), 4 * random.nextGaussian()};
            double[] d = {random.nextGaussian(), random.nextGaussian(), random.nextGaussian()};
            double tMax = random.nextBoolean() ? inf : 10 * random.nextDouble();
            double tNear = 0, tFar = tMax;
            for (int a = 0; a < 3; a++) {
                double t0 = (box[a] - o[a]) * (1 / d[a]), t1 = (box[a + 3] - o[a]) * (1 / d[a]);
                tNear = Math.max(tNear, Math.min(t0, t1));
                tFar = Math.min(tFar, Math.max(t0, t1) * Slab.FAR_WIDENING);
            }
            double entry = Slab.entry(box, 0, o[0], o[1], o[2], 1 / d[0], 1 / d[1], 1 / d[2], tMax);
            if (tNear <= tFar) {
                hits++;
                assertEquals(tNear, entry, "ray " + i);
            } else {
                assertTrue(Double.isNaN(entry), "ray " + i + " misses");
            }
        }
        assertTrue(hits > 1_000 && hits < 99_000, "both outcomes are exercised: " + hits + " hits");
    }
}

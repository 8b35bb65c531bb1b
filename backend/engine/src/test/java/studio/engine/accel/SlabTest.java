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

    @Test
    @DisplayName("for rays without NaN distances the min/max path gives the comparisons' entry to the bit, "
            + "and the any-hit test the same answer, on 200,000 rays that start on box planes, graze an edge, or carry tiny and huge components")
    void minMaxPathGivesTheComparisonsEntryBitForBit() {
        Random random = new Random(8);
        double[] box = new double[6];
        int hits = 0, onPlane = 0, grazing = 0;
        for (int i = 0; i < 200_000; i++) {
            double scale = Math.pow(10, random.nextInt(13) - 6);
            for (int a = 0; a < 3; a++) {
                double lo = scale * random.nextGaussian(), hi = lo + (random.nextInt(8) == 0 ? 0 : scale * random.nextDouble());
                box[a] = lo;
                box[a + 3] = hi;
            }
            double[] o = new double[3], inv = new double[3];
            for (int a = 0; a < 3; a++) {
                int kind = random.nextInt(6);
                // on the min or max plane (distance +-0), at the box's centre, or anywhere around it
                o[a] = kind == 0 ? box[a] : kind == 1 ? box[a + 3] : kind == 2 ? (box[a] + box[a + 3]) / 2
                        : 4 * scale * random.nextGaussian();
                onPlane += kind < 2 ? 1 : 0;
                double d = random.nextGaussian() * Math.pow(10, random.nextInt(9) - 4);
                inv[a] = 1 / (d == 0 ? 1 : d);
            }
            if (random.nextInt(4) == 0) {
                // aimed at a point on an edge (x and y on a max plane): in or out is decided by the widening
                double s = scale * (0.5 + 10 * random.nextDouble());
                double[] edge = {box[3], box[4], box[2] + (box[5] - box[2]) * random.nextDouble()};
                for (int a = 0; a < 3; a++) {
                    o[a] = edge[a] - s / inv[a];
                }
                grazing++;
            }
            assertTrue(Slab.nanFree(o[0], o[1], o[2], inv[0], inv[1], inv[2]));
            double tMax = random.nextInt(3) == 0 ? Double.POSITIVE_INFINITY : 10 * scale * random.nextDouble();
            double branchy = Slab.entry(box, 0, o[0], o[1], o[2], inv[0], inv[1], inv[2], false, tMax);
            double minMax = Slab.entry(box, 0, o[0], o[1], o[2], inv[0], inv[1], inv[2], true, tMax);
            assertEquals(Double.doubleToRawLongBits(branchy), Double.doubleToRawLongBits(minMax), "ray " + i);
            // the any-hit test's thirteen comparisons answer as the comparisons' entry does
            assertEquals(!Double.isNaN(branchy), Slab.hits(box, 0, o[0], o[1], o[2], inv[0], inv[1], inv[2], true, tMax),
                    "ray " + i);
            assertEquals(!Double.isNaN(branchy), Slab.hits(box, 0, o[0], o[1], o[2], inv[0], inv[1], inv[2], false, tMax),
                    "ray " + i);
            hits += Double.isNaN(branchy) ? 0 : 1;
        }
        assertTrue(hits > 20_000 && hits < 180_000 && onPlane > 50_000 && grazing > 40_000,
                hits + " hits, " + onPlane + " origins on planes, " + grazing + " grazing rays");
    }

    @Test
    void raysWithAZeroOrInfiniteDirectionComponentOrAnInfiniteOriginAreNotNaNFree() {
        assertTrue(Slab.nanFree(0, 0, 0, 1, -2, 3));
        assertFalse(Slab.nanFree(0, 0, 0, 1 / 0.0, 1, 1), "d.x = 0");
        assertFalse(Slab.nanFree(0, 0, 0, 1, 1 / -0.0, 1), "d.y = -0");
        assertFalse(Slab.nanFree(0, 0, 0, 1, 1, 1 / 1e-320), "d.z subnormal: 1/d.z overflows");
        assertFalse(Slab.nanFree(0, 0, 0, 1, 1, 1 / Double.POSITIVE_INFINITY), "d.z infinite: 1/d.z = 0");
        assertFalse(Slab.nanFree(Double.NEGATIVE_INFINITY, 0, 0, 1, 1, 1));
        assertFalse(Slab.nanFree(0, Double.NaN, 0, 1, 1, 1));
    }
}

package studio.engine.accel;

import studio.engine.math.Fp;

/**
 * The robust ray/box test of BVH traversal (robustness case NUM-06, docs/robustness.md; Williams et al. 2005, Ize 2013, pbrt):
 * the near and far planes of each slab are picked by the sign of the inverse direction, so a zero
 * direction component gives ±infinity; the NaN of 0*infinity (origin exactly on a slab plane) is
 * ignored by the comparisons, which counts the ray as inside that slab. Comparisons are
 * non-strict, so a flat box (a triangle's box, zmin = zmax) and a ray touching an edge are kept,
 * and every far distance is widened by 1 + 2*gamma(3) to cover the rounding of the distances.
 *
 * <p>A traversal works out once per ray whether any of its slab distances can be NaN at all
 * ({@link #nanFree}). For most rays none can, and the largest near and smallest far distance are
 * then taken with {@code Math.max} and {@code Math.min} instead of a comparison and a branch each:
 * the same values, without branches the processor mispredicts about half the time in a deep tree
 * (which of three slabs a ray enters last is a coin toss from box to box; {@code studio-bench.jar kernel}).
 *
 * <p>Whether the ray meets the box is then not asked of those two distances, at the end of the
 * chain of {@code Math.max} and {@code Math.min}, but by thirteen independent comparisons of the
 * slabs' bounds ({@link #overlap}): the same answer, ready sooner, and a traversal branches on it
 * at every box (whole processes, docs/speed.md). The images are the same to the bit.
 */
public final class Slab {

    /** The far-distance widening of Ize's robust traversal. */
    public static final double FAR_WIDENING = 1 + 2 * Fp.gamma(3);

    private Slab() {
    }

    /**
     * Where the ray o + t*d, with inverse direction (ix, iy, iz) = 1/d, enters the box stored at
     * {@code bounds[o..o+5]} if it meets it for some t in [0, tMax] (0 if it starts inside), else
     * NaN, which fails every comparison (tMax may be infinite, so no distance can mean a miss). The
     * entry distance orders a closest-hit traversal; {@link #hits} asks only whether there is one.
     */
    public static double entry(double[] bounds, int o, double ox, double oy, double oz,
                               double ix, double iy, double iz, double tMax) {
        return entry(bounds, o, ox, oy, oz, ix, iy, iz, nanFree(ox, oy, oz, ix, iy, iz), tMax);
    }

    /**
     * Whether no slab distance of this ray can be NaN: with a finite origin and finite, non-zero
     * inverse direction components, (plane - origin) * inverse multiplies a finite or infinite
     * number by a finite non-zero one, never 0 by infinity. False for a ray parallel to an axis
     * plane (a zero direction component).
     */
    public static boolean nanFree(double ox, double oy, double oz, double ix, double iy, double iz) {
        return Double.isFinite(ox) && Double.isFinite(oy) && Double.isFinite(oz)
                && Double.isFinite(ix) && ix != 0 && Double.isFinite(iy) && iy != 0 && Double.isFinite(iz) && iz != 0;
    }

    /**
     * {@link #entry(double[], int, double, double, double, double, double, double, double)} with
     * {@link #nanFree} of the ray worked out once by the caller. The same result: without NaNs the
     * maximum of 0 and the near distances, and the minimum of tMax and the far ones, are the
     * values the comparisons pick (with +0 among the candidates, {@code Math.max} gives +0 for
     * any zero, as the comparisons do).
     */
    public static double entry(double[] bounds, int o, double ox, double oy, double oz,
                               double ix, double iy, double iz, boolean nanFree, double tMax) {
        return nanFree ? entryWithoutNaN(bounds, o, ox, oy, oz, ix, iy, iz, tMax)
                : entryIgnoringNaN(bounds, o, ox, oy, oz, ix, iy, iz, tMax);
    }

    private static double entryWithoutNaN(double[] bounds, int o, double ox, double oy, double oz,
                                          double ix, double iy, double iz, double tMax) {
        double x0 = (bounds[o] - ox) * ix, x1 = (bounds[o + 3] - ox) * ix;
        double y0 = (bounds[o + 1] - oy) * iy, y1 = (bounds[o + 4] - oy) * iy;
        double z0 = (bounds[o + 2] - oz) * iz, z1 = (bounds[o + 5] - oz) * iz;
        double nearX = ix >= 0 ? x0 : x1, farX = (ix >= 0 ? x1 : x0) * FAR_WIDENING;
        double nearY = iy >= 0 ? y0 : y1, farY = (iy >= 0 ? y1 : y0) * FAR_WIDENING;
        double nearZ = iz >= 0 ? z0 : z1, farZ = (iz >= 0 ? z1 : z0) * FAR_WIDENING;
        double tNear = Math.max(Math.max(nearX, nearY), Math.max(nearZ, 0.0));
        return overlap(nearX, nearY, nearZ, farX, farY, farZ, tMax) ? tNear : Double.NaN;
    }

    /** {@link #hits} for a ray without NaN distances: {@link #overlap} of the box's slabs. */
    private static boolean hitsWithoutNaN(double[] bounds, int o, double ox, double oy, double oz,
                                          double ix, double iy, double iz, double tMax) {
        double x0 = (bounds[o] - ox) * ix, x1 = (bounds[o + 3] - ox) * ix;
        double y0 = (bounds[o + 1] - oy) * iy, y1 = (bounds[o + 4] - oy) * iy;
        double z0 = (bounds[o + 2] - oz) * iz, z1 = (bounds[o + 5] - oz) * iz;
        return overlap(ix >= 0 ? x0 : x1, iy >= 0 ? y0 : y1, iz >= 0 ? z0 : z1,
                (ix >= 0 ? x1 : x0) * FAR_WIDENING, (iy >= 0 ? y1 : y0) * FAR_WIDENING,
                (iz >= 0 ? z1 : z0) * FAR_WIDENING, tMax);
    }

    /**
     * Whether max(nearX, nearY, nearZ, 0) &lt;= min(farX, farY, farZ, tMax), asked as every near
     * bound against every far bound of another slab and against tMax, and 0 against every far
     * bound and tMax (a slab's near bound is at most its own widened far bound whenever that is
     * not negative, so those three pairs need no comparison).
     * Without NaNs that is the same answer; the thirteen comparisons are independent, and combined
     * with {@code &} (not {@code &&}) they need no branch, so the answer is ready after one
     * comparison's latency instead of after a chain of three {@code Math.max} and three
     * {@code Math.min}, and a mispredicted branch on it wastes less.
     */
    private static boolean overlap(double nearX, double nearY, double nearZ, double farX, double farY, double farZ,
                                   double tMax) {
        return (nearX <= farY) & (nearX <= farZ) & (nearX <= tMax)
                & (nearY <= farX) & (nearY <= farZ) & (nearY <= tMax)
                & (nearZ <= farX) & (nearZ <= farY) & (nearZ <= tMax)
                & (farX >= 0) & (farY >= 0) & (farZ >= 0) & (tMax >= 0);
    }

    /** The comparisons of the class comment: a NaN distance fails its comparison and so is ignored. */
    private static double entryIgnoringNaN(double[] bounds, int o, double ox, double oy, double oz,
                                           double ix, double iy, double iz, double tMax) {
        double tNear = 0, tFar = tMax;
        double near, far;
        if (ix >= 0) {
            near = (bounds[o] - ox) * ix;
            far = (bounds[o + 3] - ox) * ix;
        } else {
            near = (bounds[o + 3] - ox) * ix;
            far = (bounds[o] - ox) * ix;
        }
        if (near > tNear) {
            tNear = near;
        }
        far *= FAR_WIDENING;
        if (far < tFar) {
            tFar = far;
        }
        if (iy >= 0) {
            near = (bounds[o + 1] - oy) * iy;
            far = (bounds[o + 4] - oy) * iy;
        } else {
            near = (bounds[o + 4] - oy) * iy;
            far = (bounds[o + 1] - oy) * iy;
        }
        if (near > tNear) {
            tNear = near;
        }
        far *= FAR_WIDENING;
        if (far < tFar) {
            tFar = far;
        }
        if (iz >= 0) {
            near = (bounds[o + 2] - oz) * iz;
            far = (bounds[o + 5] - oz) * iz;
        } else {
            near = (bounds[o + 5] - oz) * iz;
            far = (bounds[o + 2] - oz) * iz;
        }
        if (near > tNear) {
            tNear = near;
        }
        far *= FAR_WIDENING;
        if (far < tFar) {
            tFar = far;
        }
        return tNear <= tFar ? tNear : Double.NaN;
    }

    /**
     * Whether the ray o + t*d, with inverse direction (ix, iy, iz) = 1/d, meets the box stored as
     * minX, minY, minZ, maxX, maxY, maxZ at {@code bounds[o..o+5]} for some t in [0, tMax].
     */
    public static boolean hits(double[] bounds, int o, double ox, double oy, double oz,
                               double ix, double iy, double iz, double tMax) {
        return !Double.isNaN(entry(bounds, o, ox, oy, oz, ix, iy, iz, tMax));
    }

    /** {@link #hits(double[], int, double, double, double, double, double, double, double)} with {@link #nanFree} given. */
    public static boolean hits(double[] bounds, int o, double ox, double oy, double oz,
                               double ix, double iy, double iz, boolean nanFree, double tMax) {
        return nanFree ? hitsWithoutNaN(bounds, o, ox, oy, oz, ix, iy, iz, tMax)
                : !Double.isNaN(entryIgnoringNaN(bounds, o, ox, oy, oz, ix, iy, iz, tMax));
    }
}

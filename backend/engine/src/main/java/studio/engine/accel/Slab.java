package studio.engine.accel;

import studio.engine.math.Fp;

/**
 * The robust ray/box test of BVH traversal (STABILITY NUM-06; Williams et al. 2005, Ize 2013, pbrt):
 * the near and far planes of each slab are picked by the sign of the inverse direction, so a zero
 * direction component gives ±infinity; the NaN of 0*infinity (origin exactly on a slab plane) is
 * ignored by the comparisons, which counts the ray as inside that slab. Comparisons are
 * non-strict, so a flat box (a triangle's box, zmin = zmax) and a ray touching an edge are kept,
 * and every far distance is widened by 1 + 2*gamma(3) to cover the rounding of the distances.
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
}

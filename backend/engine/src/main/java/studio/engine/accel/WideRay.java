package studio.engine.accel;

import studio.engine.math.Fp;

/**
 * A ray set up once for {@link WideBoxTest}s in float: the inverse direction, which of a node's
 * bound arrays is each slab's near and far plane (by the direction's sign, as {@link Slab}), and
 * the origin rounded to float once towards each plane, so that the float test stays conservative.
 * Mutable and reused: one per traversal thread.
 *
 * <p>Why the float test never drops a box the double {@link Slab} test keeps (robustness case
 * NUM-06): the boxes are rounded outward ({@link WideBvh}); the origin is rounded up where that
 * makes a near distance smaller and a far one larger, down where it does; what is left, the
 * rounding of the subtraction, of the product and of the inverse direction to float, is at most
 * gamma(3) in float of each distance, and every far distance and the caller's limit
 * ({@link #limit}) are widened by {@link #FAR_WIDENING}, twice what covers that and the double
 * test's own rounding (Ize 2013, pbrt's {@code Bounds3::IntersectP}). The NaN of 0 * infinity (an
 * axis-parallel ray whose origin lies on a slab plane) fails the test's comparisons and so leaves
 * that slab unconstrained, as in {@link Slab}. A ray whose numbers leave the range where these
 * bounds hold (a direction component beyond 1e30 or below 1e-30 in size but not zero, an origin
 * beyond 1e30, anything not finite) is marked {@link #acceptAll}: the test then keeps every box,
 * which is slow but exact.
 */
public final class WideRay {

    /** Float unit roundoff, 2^-24. */
    private static final double FLOAT_ROUNDOFF = Math.ulp(1.0f) / 2.0;
    /** gamma(3) in float, rounded up. */
    private static final double FLOAT_GAMMA_3 = Math.nextUp(3 * FLOAT_ROUNDOFF / (1 - 3 * FLOAT_ROUNDOFF));
    /** The far-distance widening of the float test: 1 + 4 gamma(3) in float, rounded up (see the class comment). */
    public static final float FAR_WIDENING = WideBvh.floatAbove(1 + 4 * FLOAT_GAMMA_3 + 4 * Fp.gamma(3));
    private static final double LARGEST = 1e30, SMALLEST = 1e-30;

    /** Inverse direction in float. */
    public float ix, iy, iz;
    /** The origin rounded towards each slab's near plane, and towards its far plane. */
    public float nearOx, nearOy, nearOz, farOx, farOy, farOz;
    /** Offsets of each slab's near and far bound array within a node ({@link WideBvh#MIN_X} ...). */
    public int nearX, nearY, nearZ, farX, farY, farZ;
    /** Whether the float test must keep every box for this ray (see the class comment). */
    public boolean acceptAll;
    /**
     * The last origin's bits and what was worked out from it: the origin rounded up and down to
     * float on each axis, and whether it is in range; rays from one point (a frame's camera rays)
     * work it out once (kernel benchmark, {@code studio-bench.jar kernel}). It starts as the
     * origin (0, 0, 0)'s: all bits zero, every rounding 0, in range.
     */
    private long lastOx, lastOy, lastOz;
    private float upX, downX, upY, downY, upZ, downZ;
    private boolean originInRange = true;

    /** Sets this up for the ray from (ox, oy, oz) along (dx, dy, dz). */
    public WideRay set(double ox, double oy, double oz, double dx, double dy, double dz) {
        long bx = Double.doubleToRawLongBits(ox), by = Double.doubleToRawLongBits(oy), bz = Double.doubleToRawLongBits(oz);
        if (bx != lastOx || by != lastOy || bz != lastOz) {
            // (near - o) * i is smallest with o rounded up when i >= 0, down when i < 0; the far one the other way
            upX = WideBvh.floatAbove(ox);
            downX = WideBvh.floatBelow(ox);
            upY = WideBvh.floatAbove(oy);
            downY = WideBvh.floatBelow(oy);
            upZ = WideBvh.floatAbove(oz);
            downZ = WideBvh.floatBelow(oz);
            originInRange = inRange(ox) && inRange(oy) && inRange(oz);
            lastOx = bx;
            lastOy = by;
            lastOz = bz;
        }
        double ixd = 1 / dx, iyd = 1 / dy, izd = 1 / dz;
        acceptAll = !(originInRange && usable(ixd) && usable(iyd) && usable(izd));
        ix = (float) ixd;
        iy = (float) iyd;
        iz = (float) izd;
        boolean px = ixd >= 0, py = iyd >= 0, pz = izd >= 0;
        nearX = px ? WideBvh.MIN_X : WideBvh.MAX_X;
        farX = px ? WideBvh.MAX_X : WideBvh.MIN_X;
        nearY = py ? WideBvh.MIN_Y : WideBvh.MAX_Y;
        farY = py ? WideBvh.MAX_Y : WideBvh.MIN_Y;
        nearZ = pz ? WideBvh.MIN_Z : WideBvh.MAX_Z;
        farZ = pz ? WideBvh.MAX_Z : WideBvh.MIN_Z;
        nearOx = px ? upX : downX;
        farOx = px ? downX : upX;
        nearOy = py ? upY : downY;
        farOy = py ? downY : upY;
        nearOz = pz ? upZ : downZ;
        farOz = pz ? downZ : upZ;
        return this;
    }

    /**
     * The float limit a box test compares entry distances with, for a double limit {@code tMax}
     * (the closest hit so far, or a shadow ray's length): rounded up and widened by
     * {@link #FAR_WIDENING}, so that a box the double test enters by tMax is kept.
     */
    public static float limit(double tMax) {
        float f = WideBvh.floatAbove(tMax);
        return f > 0 ? WideBvh.floatAbove((double) f * FAR_WIDENING) : f;
    }

    private static boolean inRange(double v) {
        return Math.abs(v) <= LARGEST;
    }

    /** An inverse direction component the float test handles exactly: infinite, or 1e-30 to 1e30 in size. */
    private static boolean usable(double inverse) {
        double a = Math.abs(inverse);
        return a == Double.POSITIVE_INFINITY || (a >= SMALLEST && a <= LARGEST);
    }
}

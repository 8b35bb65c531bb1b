package studio.engine.geometry;

/**
 * A pyramid with its apex at a point, which a BVH traversal uses to find every shape a bundle of
 * rays from that apex can meet: the camera rays of a run of pixels (apex at the camera;
 * {@link RayBundle}).
 *
 * <p>Given an axis {@code a} and two directions {@code e1}, {@code e2} across it, a point q lies
 * inside when, with r = q - apex, x = e1.r / a.r lies in [x0, x1], y = e2.r / a.r in [y0, y1], and
 * a.r is at most {@code far}. Each bound on x or y is a plane through the apex, with normal
 * e1 - x0*a, x1*a - e1, e2 - y0*a or y1*a - e2; together they also give a.r &gt;= 0.
 *
 * <p>{@link #mayMeet} must never drop a box that a ray of the bundle meets, whatever the rounding:
 * <ul>
 *   <li>the ranges are widened by {@value #MARGIN} of their scale, far more than the few units in
 *       the last place by which a computed ray (or a projected corner) can stray from the exact
 *       one;</li>
 *   <li>a box is dropped only when its corner furthest inside a plane is outside it by more than
 *       {@value #SLACK} times the magnitudes in the plane's sum, taken from the coordinates
 *       themselves (not from their differences to the apex; for the boxes, from a bound on all of
 *       them, {@link #within}). That covers the rounding of those
 *       few operations many times over, and also a hit point reported a few units in the last
 *       place off its ray where the pyramid is thinner than that: near the apex, with the camera
 *       or the light far from the origin.</li>
 * </ul>
 * A box merely near the pyramid is kept: the ray tests decide hits.
 */
public final class Frustum {

    /** How much the ranges are widened, relative to their scale. */
    static final double MARGIN = 1e-9;
    /** How far outside a plane, relative to the magnitudes summed, a box must be to be dropped. */
    static final double SLACK = 1e-12;

    private double ox, oy, oz;
    /** Doubles per plane: normal x, y, z, offset d, threshold, and for the slack |apex| and |n|. */
    private static final int STRIDE = 7;
    /**
     * The planes n.r + d &gt;= 0, four, or five with an end. A box is dropped when its corner
     * furthest along n gives less than the threshold (see {@link #within}).
     */
    private final double[] planes = new double[5 * STRIDE];
    private int planeCount;

    /**
     * Sets the pyramid: apex, axis a, the two directions across it (unit and perpendicular to a
     * and each other), the ranges of x and y, and the largest a.r (infinity: no end).
     */
    public Frustum set(double px, double py, double pz, double ax, double ay, double az,
                       double e1x, double e1y, double e1z, double e2x, double e2y, double e2z,
                       double x0, double x1, double y0, double y1, double far) {
        ox = px;
        oy = py;
        oz = pz;
        double widenX = MARGIN * Math.max(1, Math.max(Math.abs(x0), Math.abs(x1)));
        double widenY = MARGIN * Math.max(1, Math.max(Math.abs(y0), Math.abs(y1)));
        x0 -= widenX;
        x1 += widenX;
        y0 -= widenY;
        y1 += widenY;
        plane(0, e1x - x0 * ax, e1y - x0 * ay, e1z - x0 * az, 0);
        plane(1, x1 * ax - e1x, x1 * ay - e1y, x1 * az - e1z, 0);
        plane(2, e2x - y0 * ax, e2y - y0 * ay, e2z - y0 * az, 0);
        plane(3, y1 * ax - e2x, y1 * ay - e2y, y1 * az - e2z, 0);
        // a.r <= far; with no end, a plane that keeps everything
        boolean end = far < Double.POSITIVE_INFINITY;
        planeCount = end ? 5 : 4;
        plane(4, end ? -ax : 0, end ? -ay : 0, end ? -az : 0, end ? far * (1 + MARGIN) : 0);
        return this;
    }

    /**
     * Makes {@link #mayMeet} take every box it will be given to lie within {@code magnitude} of
     * the origin in each coordinate: the slack of the class comment is then worked out once per
     * plane, not per box. Until this is called, {@link #mayMeet} drops nothing.
     */
    public Frustum within(double magnitude) {
        for (int i = 0; i < planeCount * STRIDE; i += STRIDE) {
            planes[i + 4] = -SLACK * (planes[i + 6] * magnitude + planes[i + 5]);
        }
        return this;
    }

    /**
     * Whether a ray of the bundle may meet the box at {@code bounds[o .. o+5]} (minX, minY, minZ,
     * maxX, maxY, maxZ), which lies within the magnitude given to {@link #within}. False only when
     * the box lies wholly outside one of the planes.
     */
    public boolean mayMeet(double[] bounds, int o) {
        double x0 = bounds[o] - ox, y0 = bounds[o + 1] - oy, z0 = bounds[o + 2] - oz;
        double x1 = bounds[o + 3] - ox, y1 = bounds[o + 4] - oy, z1 = bounds[o + 5] - oz;
        double[] p = planes;
        for (int i = 0, end = planeCount * STRIDE; i < end; i += STRIDE) {
            double nx = p[i], ny = p[i + 1], nz = p[i + 2];
            // the box's corner furthest along the normal
            double inside = (nx >= 0 ? nx * x1 : nx * x0) + (ny >= 0 ? ny * y1 : ny * y0)
                    + (nz >= 0 ? nz * z1 : nz * z0) + p[i + 3];
            if (inside < p[i + 4]) {
                return false;
            }
        }
        return true;
    }

    private void plane(int index, double x, double y, double z, double d) {
        int at = STRIDE * index;
        planes[at] = x;
        planes[at + 1] = y;
        planes[at + 2] = z;
        planes[at + 3] = d;
        planes[at + 4] = Double.NaN; // no threshold until within(): nothing is dropped
        // the magnitudes the apex and the offset bring to the plane's sum, and the normal's
        planes[at + 5] = Math.abs(x) * Math.abs(ox) + Math.abs(y) * Math.abs(oy) + Math.abs(z) * Math.abs(oz)
                + Math.abs(d);
        planes[at + 6] = Math.abs(x) + Math.abs(y) + Math.abs(z);
    }
}

package studio.engine.geometry;

/**
 * A pyramid with its apex at a point, which a BVH traversal uses to find every shape a bundle of
 * rays from that apex can meet: the camera rays of a run of pixels (apex at the camera), or the
 * shadow rays from where they hit one object to a point light (apex at the light, the pyramid
 * holding the box of those hit points and ending behind it; {@link RayBundle}).
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

    /**
     * The smallest cosine taken where a pyramid would otherwise open too wide or a corner be
     * ill-conditioned: between an edge and a plane it meets ({@link #widenToPlane}), and between
     * the axis and a box's corner ({@link #overBox}).
     */
    static final double STEEP = 1e-3;

    private double ox, oy, oz;
    /** The four edge directions (x0 y0, x1 y0, x0 y1, x1 y1), x, y, z of each. */
    private final double[] edges = new double[12];
    /** The axis the edges were made from (each edge's component along it is 1). */
    private final double[] edgesAxis = new double[3];
    /** Scratch: the box of the points added since it was last emptied (minX, minY, minZ, maxX, maxY, maxZ). */
    private final double[] hull = new double[6];
    /** Doubles per plane: normal x, y, z, offset d, threshold, and for the slack |apex| and |n|. */
    private static final int STRIDE = 7;
    /**
     * The planes n.r + d &gt;= 0, four, or five with an end. A box is dropped when its corner
     * furthest along n gives less than the threshold (see {@link #within}).
     */
    private final double[] planes = new double[5 * STRIDE];
    private int planeCount;
    /** The largest a.r, widened as the end plane is (infinity: no end). */
    private double farEnd;

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
        edgesAxis[0] = ax;
        edgesAxis[1] = ay;
        edgesAxis[2] = az;
        for (int c = 0; c < 4; c++) {
            double x = (c & 1) == 0 ? x0 : x1, y = (c & 2) == 0 ? y0 : y1;
            edges[3 * c] = ax + x * e1x + y * e2x;
            edges[3 * c + 1] = ay + x * e1y + y * e2y;
            edges[3 * c + 2] = az + x * e1z + y * e2z;
        }
        // a.r <= far; with no end, a plane that keeps everything
        boolean end = far < Double.POSITIVE_INFINITY;
        planeCount = end ? 5 : 4;
        plane(4, end ? -ax : 0, end ? -ay : 0, end ? -az : 0, end ? far * (1 + MARGIN) : 0);
        farEnd = end ? far * (1 + MARGIN) : Double.POSITIVE_INFINITY;
        return this;
    }

    /**
     * Whether no point of the pyramid lies on the plane through (px, py, pz) with unit normal
     * (nx, ny, nz), nor within a rounding of it, so that no ray of the bundle can report a hit on
     * it: the apex clearly on one side, and, with an end, the pyramid's far corners clearly on the
     * same side (the pyramid is their hull with the apex); without one, every edge heading away
     * from the plane at a cosine of at least {@value #STEEP}. "Clearly": by more than
     * {@value #MARGIN} of the coordinates' magnitudes.
     */
    public boolean clearOf(double px, double py, double pz, double nx, double ny, double nz) {
        double side = nx * (ox - px) + ny * (oy - py) + nz * (oz - pz);
        double scale = Math.abs(ox) + Math.abs(oy) + Math.abs(oz) + Math.abs(px) + Math.abs(py) + Math.abs(pz);
        if (!(Math.abs(side) > MARGIN * scale)) {
            return false;
        }
        for (int c = 0; c < 12; c += 3) {
            double dx = edges[c], dy = edges[c + 1], dz = edges[c + 2];
            double away = Math.copySign(1, side) * (nx * dx + ny * dy + nz * dz);
            if (farEnd < Double.POSITIVE_INFINITY) {
                double cx = ox + farEnd * dx, cy = oy + farEnd * dy, cz = oz + farEnd * dz;
                double corner = nx * (cx - px) + ny * (cy - py) + nz * (cz - pz);
                double cornerScale = scale + Math.abs(cx) + Math.abs(cy) + Math.abs(cz);
                if (!(Math.copySign(1, side) * corner > MARGIN * cornerScale)) {
                    return false;
                }
            } else if (!(away >= STEEP * Math.sqrt(dx * dx + dy * dy + dz * dz))) {
                return false;
            }
        }
        return true;
    }

    /**
     * The pyramid from point (px, py, pz) over the box {@code box[0 .. 5]} (minX, minY, minZ,
     * maxX, maxY, maxZ), ending behind it: it holds every segment from the point to a point of
     * the box. False, and unchanged, when the point is not clearly outside the box (a pyramid
     * would have to open wider than a half-space).
     */
    public boolean overBox(double px, double py, double pz, double[] box) {
        double scale = 0;
        for (int k = 0; k < 6; k++) {
            scale = Math.max(scale, Math.abs(box[k]));
        }
        double widen = MARGIN * scale;
        double minX = box[0] - widen, minY = box[1] - widen, minZ = box[2] - widen;
        double maxX = box[3] + widen, maxY = box[4] + widen, maxZ = box[5] + widen;
        double ax = (minX + maxX) / 2 - px, ay = (minY + maxY) / 2 - py, az = (minZ + maxZ) / 2 - pz;
        double len = Math.sqrt(ax * ax + ay * ay + az * az);
        if (!(len > 0)) {
            return false;
        }
        ax /= len;
        ay /= len;
        az /= len;
        // e1: across the axis, from the axis's smallest component; e2 = a x e1
        double e1x, e1y, e1z;
        if (Math.abs(ax) <= Math.abs(ay) && Math.abs(ax) <= Math.abs(az)) {
            e1x = 0; e1y = az; e1z = -ay;
        } else if (Math.abs(ay) <= Math.abs(az)) {
            e1x = -az; e1y = 0; e1z = ax;
        } else {
            e1x = ay; e1y = -ax; e1z = 0;
        }
        double e1Len = Math.sqrt(e1x * e1x + e1y * e1y + e1z * e1z);
        e1x /= e1Len;
        e1y /= e1Len;
        e1z /= e1Len;
        double e2x = ay * e1z - az * e1y, e2y = az * e1x - ax * e1z, e2z = ax * e1y - ay * e1x;
        double x0 = Double.POSITIVE_INFINITY, x1 = Double.NEGATIVE_INFINITY;
        double y0 = Double.POSITIVE_INFINITY, y1 = Double.NEGATIVE_INFINITY, far = 0;
        for (int c = 0; c < 8; c++) {
            double rx = ((c & 1) == 0 ? minX : maxX) - px;
            double ry = ((c & 2) == 0 ? minY : maxY) - py;
            double rz = ((c & 4) == 0 ? minZ : maxZ) - pz;
            double s = ax * rx + ay * ry + az * rz;
            // a corner beside or behind the point, or nearly so: the pyramid would be too wide
            if (!(s > STEEP * Math.sqrt(rx * rx + ry * ry + rz * rz))) {
                return false;
            }
            double x = (e1x * rx + e1y * ry + e1z * rz) / s, y = (e2x * rx + e2y * ry + e2z * rz) / s;
            x0 = Math.min(x0, x);
            x1 = Math.max(x1, x);
            y0 = Math.min(y0, y);
            y1 = Math.max(y1, y);
            far = Math.max(far, s);
        }
        set(px, py, pz, ax, ay, az, e1x, e1y, e1z, e2x, e2y, e2z, x0, x1, y0, y1, far);
        return true;
    }

    /**
     * Widens {@code box[0 .. 5]} (minX, minY, minZ, maxX, maxY, maxZ) to hold every point of the
     * plane through (px, py, pz) with unit normal (nx, ny, nz) that lies inside this pyramid, and
     * every point a ray inside it can report as a hit on the plane. That part is the quadrilateral
     * where the four edges meet the plane, if all four meet it in front of the apex. False, and the
     * box unchanged, when they do not (the part is unbounded), when an edge meets it at a grazing
     * angle (cosine below {@value #STEEP}: the corner would be ill-conditioned), or when the
     * pyramid has an end (it was made {@link #overBox}).
     */
    public boolean widenToPlane(double px, double py, double pz, double nx, double ny, double nz, double[] box) {
        if (ends()) {
            return false;
        }
        double reach = nx * (px - ox) + ny * (py - oy) + nz * (pz - oz);
        emptyHull();
        for (int c = 0; c < 12; c += 3) {
            double dx = edges[c], dy = edges[c + 1], dz = edges[c + 2];
            double along = nx * dx + ny * dy + nz * dz;
            // in front of the apex (same sign as reach), and steep enough
            if (!(along * reach > 0) || Math.abs(along) < STEEP * Math.sqrt(dx * dx + dy * dy + dz * dz)) {
                return false;
            }
            double t = reach / along;
            addToHull(ox + t * dx, oy + t * dy, oz + t * dz);
        }
        double scale = Math.max(Math.abs(ox) + Math.abs(oy) + Math.abs(oz), Math.abs(px) + Math.abs(py) + Math.abs(pz));
        for (double v : hull) {
            scale = Math.max(scale, Math.abs(v));
        }
        double widen = MARGIN * scale;
        if (!Double.isFinite(widen)) {
            return false;
        }
        widenByHull(widen, null, 0, box);
        return true;
    }

    /**
     * Widens {@code box[0 .. 5]} to hold the part of the box at {@code shape[o .. o+5]} that lies
     * inside this pyramid (an end-less one, as {@link #widenToPlane}): every point where a ray
     * inside it can hit a shape within that box. The part is bounded by the box itself and by the
     * pyramid's slice between the box's nearest and furthest distances along the axis, which is
     * the hull of its four edges' points at those two distances. Returns false, and leaves the
     * box unchanged, when the pyramid has an end.
     */
    public boolean widenToPart(double[] shape, int o, double[] box) {
        if (ends()) {
            return false;
        }
        double ax = edgesAxis[0], ay = edgesAxis[1], az = edgesAxis[2];
        // the box's nearest and furthest distances along the axis, from its corners
        double near = (ax >= 0 ? ax * (shape[o] - ox) : ax * (shape[o + 3] - ox))
                + (ay >= 0 ? ay * (shape[o + 1] - oy) : ay * (shape[o + 4] - oy))
                + (az >= 0 ? az * (shape[o + 2] - oz) : az * (shape[o + 5] - oz));
        double far = (ax >= 0 ? ax * (shape[o + 3] - ox) : ax * (shape[o] - ox))
                + (ay >= 0 ? ay * (shape[o + 4] - oy) : ay * (shape[o + 1] - oy))
                + (az >= 0 ? az * (shape[o + 5] - oz) : az * (shape[o + 2] - oz));
        double scale = Math.abs(ox) + Math.abs(oy) + Math.abs(oz);
        for (int k = 0; k < 6; k++) {
            scale = Math.max(scale, Math.abs(shape[o + k]));
        }
        // the distances rounded outwards; nothing behind the apex
        double slack = MARGIN * (scale + Math.abs(near) + Math.abs(far));
        near = Math.max(0, near - slack);
        far += slack;
        emptyHull();
        for (int c = 0; c < 12; c += 3) {
            addToHull(ox + near * edges[c], oy + near * edges[c + 1], oz + near * edges[c + 2]);
            addToHull(ox + far * edges[c], oy + far * edges[c + 1], oz + far * edges[c + 2]);
        }
        widenByHull(MARGIN * (scale + far), shape, o, box);
        return true;
    }

    /**
     * Into {@code box} (minX, minY, minZ, maxX, maxY, maxZ): a box holding the pyramid, which must
     * end: its apex and far corners, widened by {@value #MARGIN} of their magnitudes, far more than
     * their rounding. A box that does not overlap it does not meet the pyramid.
     */
    public void bounds(double[] box) {
        if (!ends()) {
            throw new IllegalStateException("an endless pyramid has no bounds");
        }
        emptyHull();
        addToHull(ox, oy, oz);
        for (int c = 0; c < 12; c += 3) {
            addToHull(ox + farEnd * edges[c], oy + farEnd * edges[c + 1], oz + farEnd * edges[c + 2]);
        }
        double widen = MARGIN * (Math.max(Math.max(Math.abs(hull[0]), Math.abs(hull[3])),
                Math.max(Math.max(Math.abs(hull[1]), Math.abs(hull[4])), Math.max(Math.abs(hull[2]), Math.abs(hull[5])))));
        for (int k = 0; k < 3; k++) {
            box[k] = hull[k] - widen;
            box[k + 3] = hull[k + 3] + widen;
        }
    }

    /** Whether the pyramid has an end (made {@link #overBox}). */
    private boolean ends() {
        return planeCount == 5;
    }

    private void emptyHull() {
        hull[0] = hull[1] = hull[2] = Double.POSITIVE_INFINITY;
        hull[3] = hull[4] = hull[5] = Double.NEGATIVE_INFINITY;
    }

    private void addToHull(double x, double y, double z) {
        hull[0] = Math.min(hull[0], x);
        hull[1] = Math.min(hull[1], y);
        hull[2] = Math.min(hull[2], z);
        hull[3] = Math.max(hull[3], x);
        hull[4] = Math.max(hull[4], y);
        hull[5] = Math.max(hull[5], z);
    }

    /** Widens {@code box} by the hull grown by {@code widen} on every side, clipped to {@code clip[o .. o+5]} (null: not). */
    private void widenByHull(double widen, double[] clip, int o, double[] box) {
        for (int k = 0; k < 3; k++) {
            double low = hull[k] - widen, high = hull[k + 3] + widen;
            if (clip != null) {
                low = Math.max(clip[o + k], low);
                high = Math.min(clip[o + k + 3], high);
            }
            box[k] = Math.min(box[k], low);
            box[k + 3] = Math.max(box[k + 3], high);
        }
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

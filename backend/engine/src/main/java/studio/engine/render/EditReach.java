package studio.engine.render;

/**
 * Where one edit noted by {@link PixelPaths} can reach: the changed objects' boxes (the union
 * first, then each, if more than one), each with the ball that holds its object where it has one
 * (a sphere: its own ball, far tighter than its box seen from the side), and the test of a segment
 * or ray against them, conservative: a box and a ball are widened by a margin far beyond the
 * rounding of the floats the points are kept in, and a NaN distance (a point on a box's plane with
 * a zero direction component) counts as inside. A segment may meet an object only if it meets
 * both its box and its ball.
 *
 * @param box    6 numbers a box (min x, y, z, max x, y, z): the union, then each if several
 * @param ball   4 numbers a box (centre x, y, z, radius): the ball around that box's object, or a
 *               negative radius for none; the union's holds every object's ball, if each has one
 * @param margin the margin's share of the largest coordinate involved
 */
record EditReach(double[] box, double[] ball, boolean several, double scale, double margin) {

    /** Whether a + t d, 0 &lt;= t &lt;= tMax, may meet a changed object. */
    boolean meets(double ax, double ay, double az, double dx, double dy, double dz, double tMax) {
        double size = Math.max(scale, Math.max(Math.abs(ax), Math.max(Math.abs(ay), Math.abs(az))));
        if (tMax == 1) {
            size = Math.max(size, Math.max(Math.abs(ax + dx), Math.max(Math.abs(ay + dy), Math.abs(az + dz))));
        }
        double widen = margin * (1 + size);
        if (!meets(0, ax, ay, az, dx, dy, dz, tMax, widen)) {
            return false;
        }
        if (!several) {
            return true;
        }
        for (int o = 1; 6 * o < box.length; o++) {
            if (meets(o, ax, ay, az, dx, dy, dz, tMax, widen)) {
                return true;
            }
        }
        return false;
    }

    private boolean meets(int i, double ax, double ay, double az, double dx, double dy, double dz, double tMax,
                          double widen) {
        return meetsBox(6 * i, ax, ay, az, dx, dy, dz, tMax, widen)
                && (ball[4 * i + 3] < 0 || meetsBall(4 * i, ax, ay, az, dx, dy, dz, tMax, widen));
    }

    /** Whether the segment passes within the ball's radius and the margin of its centre; true for a zero direction. */
    private boolean meetsBall(int o, double ax, double ay, double az, double dx, double dy, double dz, double tMax,
                              double widen) {
        double ox = ball[o] - ax, oy = ball[o + 1] - ay, oz = ball[o + 2] - az, reach = ball[o + 3] + widen;
        double dd = dx * dx + dy * dy + dz * dz;
        if (!(dd > 0)) {
            return true;
        }
        double t = Math.min(tMax, Math.max(0, (ox * dx + oy * dy + oz * dz) / dd));
        double ex = ox - t * dx, ey = oy - t * dy, ez = oz - t * dz;
        // a NaN (an infinite direction) fails the comparison: inside
        return !(ex * ex + ey * ey + ez * ez > reach * reach);
    }

    private boolean meetsBox(int o, double ax, double ay, double az, double dx, double dy, double dz, double tMax,
                             double widen) {
        double ix = 1 / dx, iy = 1 / dy, iz = 1 / dz;
        double x0 = (box[o] - widen - ax) * ix, x1 = (box[o + 3] + widen - ax) * ix;
        double y0 = (box[o + 1] - widen - ay) * iy, y1 = (box[o + 4] + widen - ay) * iy;
        double z0 = (box[o + 2] - widen - az) * iz, z1 = (box[o + 5] + widen - az) * iz;
        // a NaN (0 times infinity: a point on a plane of the box, moving along it) fails every
        // comparison and so leaves the ray inside that slab
        double near = 0, far = tMax;
        if (Math.min(x0, x1) > near) {
            near = Math.min(x0, x1);
        }
        if (Math.max(x0, x1) < far) {
            far = Math.max(x0, x1);
        }
        if (Math.min(y0, y1) > near) {
            near = Math.min(y0, y1);
        }
        if (Math.max(y0, y1) < far) {
            far = Math.max(y0, y1);
        }
        if (Math.min(z0, z1) > near) {
            near = Math.min(z0, z1);
        }
        if (Math.max(z0, z1) < far) {
            far = Math.max(z0, z1);
        }
        return !(near > far);
    }

    /**
     * A quick first test of the segments from one point (the camera, a light) to the pixels' hit
     * points against the changed objects: the cone from the point around a sphere that holds them
     * (the union's ball, or the sphere around the union box), widened past the margin and the
     * floats' rounding (a hit point kept as floats is off by at most 1.2e-7 of its largest
     * coordinate; seen from the apex at least half the sphere's distance away, that turns the
     * segment by less than the widening). A segment that leaves the cone, or ends before the
     * sphere, cannot meet the objects; one inside is tested exactly. Without a cone (the apex
     * within twice the sphere's radius) every segment is.
     */
    Cone cone(double ax, double ay, double az) {
        double cx, cy, cz, held;
        if (ball[3] >= 0) {
            cx = ball[0];
            cy = ball[1];
            cz = ball[2];
            held = ball[3];
        } else {
            cx = (box[0] + box[3]) / 2;
            cy = (box[1] + box[4]) / 2;
            cz = (box[2] + box[5]) / 2;
            double hx = (box[3] - box[0]) / 2, hy = (box[4] - box[1]) / 2, hz = (box[5] - box[2]) / 2;
            held = Math.sqrt(hx * hx + hy * hy + hz * hz);
        }
        double radius = held * (1 + 1e-9) + 2 * margin * (1 + scale + Math.abs(ax) + Math.abs(ay) + Math.abs(az));
        double wx = cx - ax, wy = cy - ay, wz = cz - az;
        double d2 = wx * wx + wy * wy + wz * wz, d = Math.sqrt(d2);
        boolean active = d > 2 * radius;
        return new Cone(ax, ay, az, wx, wy, wz, d2 - radius * radius, active ? (d - radius) * (d - radius) : 0, active);
    }

    /** The cone from an apex around the changed objects' sphere ({@link #cone}). */
    record Cone(double ax, double ay, double az, double wx, double wy, double wz, double k, double minLength2,
                boolean active) {

        /** Whether the segment from the apex to (px, py, pz) may meet the sphere. */
        boolean mayMeet(double px, double py, double pz) {
            if (!active) {
                return true;
            }
            double vx = px - ax, vy = py - ay, vz = pz - az;
            double dot = vx * wx + vy * wy + vz * wz;
            double v2 = vx * vx + vy * vy + vz * vz;
            return dot > 0 && dot * dot >= v2 * k && v2 >= minLength2;
        }
    }
}

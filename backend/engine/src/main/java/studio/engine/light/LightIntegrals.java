package studio.engine.light;

/**
 * What a point gets from the whole of a light with a size, unshadowed: the mean over the light of
 * what {@link LightSampler}'s samples give times the cosine at the point, worked out rather than
 * sampled. Each holds only while the whole light lies above the point's horizon (no cosine is
 * clipped); the caller checks that.
 *
 * <ul>
 * <li>A sphere seen under half-angle theta_max, its axis at cosine c to the normal: the samples are
 * uniform over the cone, whose mean cosine to the axis is (1 + cos theta_max) / 2, so the mean of
 * the cosine at the point is c (1 + cos theta_max) / 2.</li>
 * <li>A rectangle, with fall-off: the mean over its area of cos_l cos / d^2 is its projected solid
 * angle over its area, and the projected solid angle of a polygon is Lambert's sum over its edges,
 * exact.</li>
 * <li>A rectangle without fall-off: the mean of cos_l cos has no closed form (its 1 / d^2 part is
 * not elementary over a rectangle), so it is a Gauss-Legendre product rule, its order on each side
 * chosen from that side's length over the point's distance to the light's plane: at most 3e-5 of
 * the value (LightIntegralsTest, against a fine midpoint rule). A point nearer the plane than a
 * quarter of a side is left to sampling.</li>
 * </ul>
 */
final class LightIntegrals {

    private LightIntegrals() {
    }

    /** Longest side over the distance to the plane for which {@link #cosineProduct} answers. */
    static final double MAX_SIDE_OVER_DISTANCE = 4;
    /** Gauss-Legendre orders, and the side-over-distance ratios each is used up to. */
    private static final int[] ORDERS = {3, 4, 6, 8, 12};
    private static final double[] UP_TO = {0.5, 1, 2, 3, MAX_SIDE_OVER_DISTANCE};
    /** Per order in {@link #ORDERS}: its nodes on [-1, 1] and their weights. */
    private static final double[][] NODES = new double[ORDERS.length][], WEIGHTS = new double[ORDERS.length][];

    static {
        for (int k = 0; k < ORDERS.length; k++) {
            int n = ORDERS[k];
            NODES[k] = new double[n];
            WEIGHTS[k] = new double[n];
            for (int i = 0; i < n; i++) {
                // Newton's method on the Legendre polynomial P_n from the usual first guess
                double z = Math.cos(Math.PI * (i + 0.75) / (n + 0.5)), derivative = 0;
                for (int step = 0; step < 100; step++) {
                    double p1 = 1, p2 = 0;
                    for (int j = 1; j <= n; j++) {
                        double p3 = p2;
                        p2 = p1;
                        p1 = ((2 * j - 1) * z * p2 - (j - 1) * p3) / j;
                    }
                    derivative = n * (z * p1 - p2) / (z * z - 1);
                    double last = z;
                    z = last - p1 / derivative;
                    if (Math.abs(z - last) < 1e-16) {
                        break;
                    }
                }
                NODES[k][i] = z;
                WEIGHTS[k][i] = 2 / ((1 - z * z) * derivative * derivative);
            }
        }
    }

    /**
     * The mean cosine at the point over a sphere light's cap: {@code cosAxis} is the cosine between
     * the normal and the direction to the centre, {@code cosMax} the cone's cos theta_max.
     */
    static double sphere(double cosAxis, double cosMax) {
        return cosAxis * (1 + cosMax) / 2;
    }

    /**
     * The projected solid angle of the quadrilateral with corners (x[k], y[k], z[k]) relative to the
     * point, in order around it, for the unit normal (nx, ny, nz): Lambert's
     * 1/2 |sum_k theta_k n . (u_k x u_k+1) / |u_k x u_k+1||, u the corners' unit directions and
     * theta_k the angle between two neighbours, from atan2 (acos loses the digits of small angles).
     */
    static double projectedSolidAngle(double[] x, double[] y, double[] z, double nx, double ny, double nz) {
        double sum = 0;
        for (int k = 0; k < 4; k++) {
            int j = (k + 1) & 3;
            double la = Math.sqrt(x[k] * x[k] + y[k] * y[k] + z[k] * z[k]);
            double lb = Math.sqrt(x[j] * x[j] + y[j] * y[j] + z[j] * z[j]);
            double ax = x[k] / la, ay = y[k] / la, az = z[k] / la, bx = x[j] / lb, by = y[j] / lb, bz = z[j] / lb;
            double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
            double sin = Math.sqrt(cx * cx + cy * cy + cz * cz);
            if (sin > 0) {
                sum += Math.atan2(sin, ax * bx + ay * by + az * bz) * (nx * cx + ny * cy + nz * cz) / sin;
            }
        }
        return Math.abs(sum) / 2;
    }

    /**
     * The integral of cos_l cos over the rectangle [x0, x1] x [y0, y1] of a plane at distance h from
     * the point, in coordinates along the plane from the point's foot on it: cos_l = h / d and
     * cos = (a h + b x + c y) / d, with a, b, c the normal's components towards the plane and along
     * x and y. NaN when a side is longer than {@link #MAX_SIDE_OVER_DISTANCE} times h.
     */
    static double cosineProduct(double x0, double x1, double y0, double y1, double h, double a, double b, double c) {
        int ox = order((x1 - x0) / h), oy = order((y1 - y0) / h);
        if (ox < 0 || oy < 0) {
            return Double.NaN;
        }
        double[] nodesX = NODES[ox], weightsX = WEIGHTS[ox], nodesY = NODES[oy], weightsY = WEIGHTS[oy];
        double midX = (x0 + x1) / 2, halfX = (x1 - x0) / 2, midY = (y0 + y1) / 2, halfY = (y1 - y0) / 2;
        double hh = h * h, ah = a * h, sum = 0;
        for (int j = 0; j < nodesY.length; j++) {
            double y = midY + halfY * nodesY[j], row = 0, base = hh + y * y, top = ah + c * y;
            for (int i = 0; i < nodesX.length; i++) {
                double x = midX + halfX * nodesX[i];
                row += weightsX[i] * (top + b * x) / (base + x * x);
            }
            sum += weightsY[j] * row;
        }
        return h * sum * halfX * halfY;
    }

    /** Whether {@link #cosineProduct} answers for a rectangle of these sides at this distance from its plane. */
    static boolean answers(double width, double height, double distance) {
        double most = MAX_SIDE_OVER_DISTANCE * distance;
        return width <= most && height <= most;
    }

    /** The index in {@link #ORDERS} of the order for a side this many times the distance, or -1: too long. */
    private static int order(double sideOverDistance) {
        for (int k = 0; k < UP_TO.length; k++) {
            if (sideOverDistance <= UP_TO[k]) {
                return k;
            }
        }
        return -1;
    }
}

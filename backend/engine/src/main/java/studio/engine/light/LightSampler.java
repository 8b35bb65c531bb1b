package studio.engine.light;

import java.util.List;

import studio.engine.geometry.Ray;
import studio.engine.geometry.Shape;

/**
 * Picks the point of a light a shadow ray goes to, and what that sample gives: one per worker
 * thread, filled by {@link #sample} and read from its fields; it allocates nothing after
 * construction.
 *
 * <ul>
 * <li>A point light: its position, and colour * intensity (over d^2 with fall-off), computed as
 * the renderer always has, to the bit.</li>
 * <li>A sphere light: a direction in the cone of the cap the point sees, uniform in solid angle
 * (pbrt-v4's SphereLight, "sampling spheres"), and the sphere's surface along it. (u, v) reaches the
 * cone through Shirley and Chiu's concentric map of the square onto the disc, so each stratum of a
 * stratified (u, v) is a compact piece of the cap, not a ring or a half-wedge, and a shadow edge
 * across the cap cuts fewer of them (PenumbraTest's wall under a sphere light at 16 jittered samples:
 * 0.65 of the polar map's squared error). With fall-off the
 * estimate is L * Omega = (I / (pi r^2)) * 2 pi (1 - cos theta_max) = 2 I / (d^2 (1 + cos theta_max)),
 * in which r cancels, so a radius of 1e-6 or of 100 has no 1/r^2 to lose digits in; 1 - cos theta_max
 * is never formed by subtraction: cos theta_max = sqrt((d - r)(d + r)) / d, and a sampled
 * sin^2 theta = a (2 - a) with a = rho^2 (1 - cos theta_max), rho the 2D point's radius on the
 * concentric disc. Without fall-off it is I.</li>
 * <li>An area light: a point on the rectangle, uniform by area, and I cos_l / d^2 (with fall-off;
 * radiance I / A over the pdf 1 / A in area, turned into solid angle by cos_l / d^2) or I cos_l
 * (without); nothing from behind a one-sided light.</li>
 * </ul>
 * The 2D point (u, v) in [0, 1)^2 comes from the pixel sampler; light i shifts it by i times the
 * plastic number's (1 / phi_2, 1 / phi_2^2), modulo 1 (a toroidal shift keeps the strata), so that
 * two lights do not sample the same spot of their shapes in step.
 */
public final class LightSampler {

    private static final int POINT = LightArrays.POINT, SPHERE = LightArrays.SPHERE, AREA = LightArrays.AREA;
    private static final double SHIFT_U = 0.7548776662466927, SHIFT_V = 0.5698402909980532;

    private final int[] kind;
    private final boolean[] falloff, twoSided;
    /** Per light: centre, colour * intensity, radius (sphere), normal and half axes (area). */
    private final double[] cx, cy, cz, er, eg, eb, radius;
    private final double[] nx, ny, nz, wx, wy, wz, hx, hy, hz;

    /** Unit direction from the point to the sample. */
    public double lx, ly, lz;
    /** The point sampled on the light: where the shadow ray ends. */
    public double tx, ty, tz;
    /** What the sample gives the point, per channel, before the cosine at the point and shadowing. */
    public double r, g, b;

    public LightSampler(List<? extends Light> lights) {
        LightArrays a = new LightArrays(lights);
        kind = a.kind;
        falloff = a.falloff;
        twoSided = a.twoSided;
        cx = a.cx; cy = a.cy; cz = a.cz;
        er = a.er; eg = a.eg; eb = a.eb;
        radius = a.radius;
        nx = a.nx; ny = a.ny; nz = a.nz;
        wx = a.wx; wy = a.wy; wz = a.wz;
        hx = a.hx; hy = a.hy; hz = a.hz;
    }

    /**
     * Samples light i as seen from point (px, py, pz) with the 2D point (u, v) into the fields.
     *
     * @return false when the light gives the point nothing: the point is on a point light, inside a
     * sphere light, or behind (or in the plane of) a one-sided area light
     */
    public boolean sample(int i, double px, double py, double pz, double u, double v) {
        return switch (kind[i]) {
            case POINT -> point(i, px, py, pz);
            case SPHERE -> sphere(i, px, py, pz, shift(u, i * SHIFT_U), shift(v, i * SHIFT_V));
            default -> area(i, px, py, pz, shift(u, i * SHIFT_U), shift(v, i * SHIFT_V));
        };
    }

    private static double shift(double u, double by) {
        double s = u + by;
        s -= Math.floor(s);
        return s < 1 ? s : Math.nextDown(1.0);
    }

    private boolean point(int i, double px, double py, double pz) {
        double x = cx[i] - px, y = cy[i] - py, z = cz[i] - pz;
        double dist = Math.sqrt(x * x + y * y + z * z);
        double pLen = Math.abs(px) + Math.abs(py) + Math.abs(pz);
        if (!(dist > 1e-12 * (1 + pLen))) {
            return false; // a light on the point itself lights nothing
        }
        lx = x / dist; ly = y / dist; lz = z / dist;
        tx = cx[i]; ty = cy[i]; tz = cz[i];
        r = er[i]; g = eg[i]; b = eb[i];
        if (falloff[i]) {
            double inverseSquare = 1 / (dist * dist);
            r *= inverseSquare;
            g *= inverseSquare;
            b *= inverseSquare;
        }
        return true;
    }

    private boolean sphere(int i, double px, double py, double pz, double u, double v) {
        double x = cx[i] - px, y = cy[i] - py, z = cz[i] - pz;
        double d = Math.sqrt(x * x + y * y + z * z), rad = radius[i];
        if (!(d > rad)) {
            return false; // inside the light (or NaN)
        }
        double inverse = 1 / d;
        x *= inverse; y *= inverse; z *= inverse;
        double sinMax = rad * inverse;
        double onePlusCosMax = 1 + Math.sqrt((d - rad) * (d + rad)) * inverse;
        double overOnePlus = 1 / onePlusCosMax;
        double oneMinusCosMax = sinMax * sinMax * overOnePlus;
        // (u, v) to the unit disc by Shirley and Chiu's concentric map, which keeps strata compact
        // (polar (u, v) makes them rings and wedges); the disc's r^2, uniform, is the cap's share a / (1 - cos theta_max).
        // Its angle is pi/4 * w, |w| <= 1, or pi/2 less that: cosine and sine from their series (see cosQuarter)
        double su = 2 * u - 1, sv = 2 * v - 1, disc, cosPhi, sinPhi;
        if (Math.abs(su) > Math.abs(sv)) {
            double w = sv / su;
            disc = su;
            cosPhi = cosQuarter(w);
            sinPhi = sinQuarter(w);
        } else if (sv != 0) {
            double w = su / sv;
            disc = sv;
            cosPhi = sinQuarter(w);
            sinPhi = cosQuarter(w);
        } else {
            disc = 0;
            cosPhi = 1;
            sinPhi = 0;
        }
        double a = disc * disc * oneMinusCosMax;
        double cos = 1 - a, sin = Math.copySign(Math.sqrt(a * (2 - a)), disc);
        double sc = sin * cosPhi, ss = sin * sinPhi;
        // an orthonormal frame (s, t, w) around w = (x, y, z) (Duff et al. 2017)
        double sign = Math.copySign(1.0, z), e = -1 / (sign + z), f = x * y * e;
        double sx = 1 + sign * x * x * e, sy = sign * f, sz = -sign * x;
        double qx = f, qy = sign + y * y * e, qz = -y;
        lx = sc * sx + ss * qx + cos * x;
        ly = sc * sy + ss * qy + cos * y;
        lz = sc * sz + ss * qz + cos * z;
        // the near root of |p + t l - c| = r: t = (d^2 - r^2) / (d cos + sqrt(r^2 - d^2 sin^2)), no cancellation
        double ds = d * Math.abs(sin);
        double root = Math.sqrt(Math.max(0, (rad - ds) * (rad + ds)));
        double t = (d - rad) * (d + rad) / (d * cos + root);
        tx = px + t * lx; ty = py + t * ly; tz = pz + t * lz;
        double k = falloff[i] ? 2 * inverse * inverse * overOnePlus : 1;
        r = er[i] * k; g = eg[i] * k; b = eb[i] * k;
        return true;
    }

    private static final double QUARTER_PI = Math.PI / 4;

    /**
     * cos(pi/4 w) for |w| &lt;= 1, from its Taylor series to the 16th power (the next term is below
     * 3e-18): a sphere light's sample took about half the time with these than with Math.cos and
     * Math.sin (soft-ball's penumbra, where they ran once a sample).
     */
    static double cosQuarter(double w) {
        double t = QUARTER_PI * w, q = t * t;
        return 1 + q * (-1.0 / 2 + q * (1.0 / 24 + q * (-1.0 / 720 + q * (1.0 / 40320 + q * (-1.0 / 3628800
                + q * (1.0 / 479001600 + q * (-1.0 / 87178291200.0 + q * (1.0 / 20922789888000.0))))))));
    }

    /** sin(pi/4 w) for |w| &lt;= 1, from its Taylor series to the 15th power (the next term is below 5e-17). */
    static double sinQuarter(double w) {
        double t = QUARTER_PI * w, q = t * t;
        return t * (1 + q * (-1.0 / 6 + q * (1.0 / 120 + q * (-1.0 / 5040 + q * (1.0 / 362880 + q * (-1.0 / 39916800
                + q * (1.0 / 6227020800.0 + q * (-1.0 / 1307674368000.0))))))));
    }

    /** Whether light i has a size (a sphere or area light): its shadows have penumbrae. */
    public boolean soft(int i) {
        return kind[i] != POINT;
    }

    /** The sides of the polygon around a sphere light's cone that {@link #hiddenBy} tests. */
    static final int SPHERE_SIDES = 8;
    private static final double POLYGON_REACH = (1 + 1e-9) / Math.cos(Math.PI / SPHERE_SIDES);
    /** The polygon's corners' directions around the axis: cosine and sine of 2 pi k / {@value #SPHERE_SIDES}. */
    private static final double[] CORNER_COS = new double[SPHERE_SIDES], CORNER_SIN = new double[SPHERE_SIDES];

    static {
        for (int k = 0; k < SPHERE_SIDES; k++) {
            CORNER_COS[k] = Math.cos(2 * Math.PI * k / SPHERE_SIDES);
            CORNER_SIN[k] = Math.sin(2 * Math.PI * k / SPHERE_SIDES);
        }
    }

    /** As a shadow ray's: blocked only before this fraction of the way to the light. */
    private static final double SHADOW_END = 1 - 1e-9;

    /**
     * Whether {@code blocker} alone hides all of sphere or area light i from the point (ox, oy, oz):
     * the point lies in the light's umbra, not in a penumbra. Exact, and cheap: the blocker is convex
     * ({@link Shape#convex}), so the rays from the point that it stops form a convex cone, and when
     * it stops the rays to an area light's 4 corners it stops the ray to every point of the
     * rectangle between them; for a sphere light, the rays through the corners of an
     * {@value #SPHERE_SIDES}-sided polygon around the cone the sphere fills, each stopped nearer than
     * the sphere's nearest point. False for a shape that is not convex (a mesh), whatever it hides,
     * and for a point light. {@code probe} is the caller's ray, set here.
     */
    public boolean hiddenBy(int i, Shape blocker, double ox, double oy, double oz, Ray probe) {
        if (kind[i] == POINT || !blocker.convex()) {
            return false;
        }
        if (kind[i] == AREA) {
            for (int corner = 0; corner < 4; corner++) {
                double su = (corner & 1) == 0 ? -1 : 1, sv = (corner & 2) == 0 ? -1 : 1;
                double x = cx[i] + su * wx[i] + sv * hx[i] - ox, y = cy[i] + su * wy[i] + sv * hy[i] - oy,
                        z = cz[i] + su * wz[i] + sv * hz[i] - oz;
                double dist = Math.sqrt(x * x + y * y + z * z);
                if (!(dist > 0) || !blocker.occluded(probe.set(ox, oy, oz, x / dist, y / dist, z / dist), dist * SHADOW_END)) {
                    return false;
                }
            }
            return true;
        }
        double x = cx[i] - ox, y = cy[i] - oy, z = cz[i] - oz;
        double d = Math.sqrt(x * x + y * y + z * z), rad = radius[i];
        if (!(d > rad)) {
            return false;
        }
        x /= d; y /= d; z /= d;
        // the polygon's corners at unit distance along the axis, a little outside the cone of half-angle theta_max
        double reach = rad / Math.sqrt((d - rad) * (d + rad)) * POLYGON_REACH;
        double sign = Math.copySign(1.0, z), e = -1 / (sign + z), f = x * y * e;
        double sx = 1 + sign * x * x * e, sy = sign * f, sz = -sign * x;
        double qx = f, qy = sign + y * y * e, qz = -y;
        for (int k = 0; k < SPHERE_SIDES; k++) {
            double c = reach * CORNER_COS[k], s = reach * CORNER_SIN[k];
            double dx = x + c * sx + s * qx, dy = y + c * sy + s * qy, dz = z + c * sz + s * qz;
            double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
            if (!blocker.occluded(probe.set(ox, oy, oz, dx / len, dy / len, dz / len), d - rad)) {
                return false;
            }
        }
        return true;
    }

    private boolean area(int i, double px, double py, double pz, double u, double v) {
        double su = 2 * u - 1, sv = 2 * v - 1;
        double qx = cx[i] + su * wx[i] + sv * hx[i], qy = cy[i] + su * wy[i] + sv * hy[i],
                qz = cz[i] + su * wz[i] + sv * hz[i];
        double x = qx - px, y = qy - py, z = qz - pz;
        double dist = Math.sqrt(x * x + y * y + z * z);
        if (!(dist > 0)) {
            return false;
        }
        lx = x / dist; ly = y / dist; lz = z / dist;
        double cosLight = -(nx[i] * lx + ny[i] * ly + nz[i] * lz);
        if (twoSided[i]) {
            cosLight = Math.abs(cosLight);
        }
        if (!(cosLight > 0)) {
            return false;
        }
        tx = qx; ty = qy; tz = qz;
        double k = falloff[i] ? cosLight / (dist * dist) : cosLight;
        r = er[i] * k; g = eg[i] * k; b = eb[i] * k;
        return true;
    }
}

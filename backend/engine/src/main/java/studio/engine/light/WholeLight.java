package studio.engine.light;

import java.util.List;

import studio.engine.geometry.Frustum;

/**
 * Whether a point may see all of a sphere or area light, and then what all of it gives the point:
 * the exact mean of what {@link LightSampler}'s samples give ({@link LightIntegrals}), so that a
 * point nothing shadows needs neither a shadow ray nor a light sample for its diffuse light. One
 * per worker thread, filled by {@link #whole} and {@link #light} and read from its fields; it
 * allocates nothing after construction. That nothing stands in the way is the caller's to prove,
 * over the pyramid {@link #whole} sets.
 */
public final class WholeLight {

    private static final int SPHERE = LightArrays.SPHERE, AREA = LightArrays.AREA;
    /** How clearly a light must lie above a point's horizon for {@link #whole}: far more than rounding. */
    private static final double ABOVE = 1e-9;

    /** The lights, as arrays. */
    private final LightArrays lights;
    /** {@link #light}'s scratch: an area light's corners relative to the point. */
    private final double[] cornerX = new double[4], cornerY = new double[4], cornerZ = new double[4];

    /** What all of the light gives the point, per channel, its cosine included ({@link #light}). */
    public double r, g, b;
    /** What the last true {@link #whole} found that {@link #light} needs. */
    private double wholeFactor, wholeX0, wholeX1, wholeY0, wholeY1, wholeH, wholeA, wholeB, wholeC;
    private double wholeNx, wholeNy, wholeNz, wholeDx, wholeDy, wholeDz;

    public WholeLight(List<? extends Light> lights) {
        this.lights = new LightArrays(lights);
    }

    /**
     * After a true {@link #whole} for light i: sets r, g, b to what all of it gives the point
     * unshadowed, the cosine at the point included: the mean over the light of what
     * {@link LightSampler#sample} gives times that cosine ({@link LightIntegrals}).
     */
    public void light(int i) {
        double k, area = 4 * lights.halfWidth[i] * lights.halfHeight[i];
        if (lights.kind[i] == SPHERE) {
            k = wholeFactor;
        } else if (lights.falloff[i]) {
            for (int corner = 0; corner < 4; corner++) {
                // in order around the rectangle: (-, -), (+, -), (+, +), (-, +)
                double su = corner == 1 || corner == 2 ? 1 : -1, sv = corner >= 2 ? 1 : -1;
                cornerX[corner] = wholeDx + su * lights.wx[i] + sv * lights.hx[i];
                cornerY[corner] = wholeDy + su * lights.wy[i] + sv * lights.hy[i];
                cornerZ[corner] = wholeDz + su * lights.wz[i] + sv * lights.hz[i];
            }
            k = LightIntegrals.projectedSolidAngle(cornerX, cornerY, cornerZ, wholeNx, wholeNy, wholeNz) / area;
        } else {
            k = LightIntegrals.cosineProduct(wholeX0, wholeX1, wholeY0, wholeY1, wholeH, wholeA, wholeB, wholeC) / area;
        }
        r = lights.er[i] * k; g = lights.eg[i] * k; b = lights.eb[i] * k;
    }

    /**
     * If the point (px, py, pz) sees all of sphere or area light i above the horizons of its shading
     * normal (nx, ny, nz) and its geometric normal (mx, my, mz), both unit and on the light's side:
     * sets {@code pyramid} to one holding every segment from the point to the light, and returns
     * true; then {@link #light} gives what all of the light gives the point unshadowed. False
     * elsewhere, and where that is left to sampling (an area light without fall-off seen from within
     * a quarter of a side of its plane).
     */
    public boolean whole(int i, double px, double py, double pz, double nx, double ny, double nz,
                         double mx, double my, double mz, Frustum pyramid) {
        return switch (lights.kind[i]) {
            case SPHERE -> wholeSphere(i, px, py, pz, nx, ny, nz, mx, my, mz, pyramid);
            case AREA -> wholeArea(i, px, py, pz, nx, ny, nz, mx, my, mz, pyramid);
            default -> false;
        };
    }

    private boolean wholeSphere(int i, double px, double py, double pz, double nx, double ny, double nz,
                                double mx, double my, double mz, Frustum pyramid) {
        double x = lights.cx[i] - px, y = lights.cy[i] - py, z = lights.cz[i] - pz;
        double d = Math.sqrt(x * x + y * y + z * z), rad = lights.radius[i];
        if (!(d > rad)) {
            return false;
        }
        x /= d; y /= d; z /= d;
        // the cone of half-angle theta_max around the axis lies above a horizon where the axis's
        // cosine exceeds sin theta_max
        double sinMax = rad / d, root = Math.sqrt((d - rad) * (d + rad));
        double cosAxis = nx * x + ny * y + nz * z;
        if (!(cosAxis > sinMax + ABOVE) || !(mx * x + my * y + mz * z > sinMax + ABOVE)) {
            return false;
        }
        // with fall-off the sample's 2 I / (d^2 (1 + cos theta_max)) times the mean cosine: I cos / d^2
        wholeFactor = lights.falloff[i] ? cosAxis / (d * d) : LightIntegrals.sphere(cosAxis, root / d);
        double tan = rad / root;
        double sign = Math.copySign(1.0, z), e = -1 / (sign + z), f = x * y * e;
        pyramid.set(px, py, pz, x, y, z, 1 + sign * x * x * e, sign * f, -sign * x, f, sign + y * y * e, -y,
                -tan, tan, -tan, tan, d);
        return true;
    }

    private boolean wholeArea(int i, double px, double py, double pz, double nx, double ny, double nz,
                              double mx, double my, double mz, Frustum pyramid) {
        double dx = lights.cx[i] - px, dy = lights.cy[i] - py, dz = lights.cz[i] - pz;
        double lnx = lights.nx[i], lny = lights.ny[i], lnz = lights.nz[i];
        // the point's height in front of the light's plane; (ax, ay, az): unit, from the point towards the plane
        double side = -(lnx * dx + lny * dy + lnz * dz);
        if (!(side > 0) && !(lights.twoSided[i] && side < 0)) {
            return false;
        }
        double h = Math.abs(side), toward = -Math.copySign(1.0, side);
        double ax = toward * lnx, ay = toward * lny, az = toward * lnz;
        double w = lights.halfWidth[i], t = lights.halfHeight[i];
        double ux = lights.ux[i], uy = lights.uy[i], uz = lights.uz[i];
        double vx = lights.vx[i], vy = lights.vy[i], vz = lights.vz[i];
        // the rectangle above both horizons: its lowest corner, at the centre's height less both half axes'
        double margin = ABOVE * (Math.abs(dx) + Math.abs(dy) + Math.abs(dz) + w + t);
        if (!(nx * dx + ny * dy + nz * dz - Math.abs(nx * lights.wx[i] + ny * lights.wy[i] + nz * lights.wz[i])
                - Math.abs(nx * lights.hx[i] + ny * lights.hy[i] + nz * lights.hz[i]) > margin)
                || !(mx * dx + my * dy + mz * dz - Math.abs(mx * lights.wx[i] + my * lights.wy[i] + mz * lights.wz[i])
                - Math.abs(mx * lights.hx[i] + my * lights.hy[i] + mz * lights.hz[i]) > margin)) {
            return false;
        }
        double mid = ux * dx + uy * dy + uz * dz, midV = vx * dx + vy * dy + vz * dz;
        if (!lights.falloff[i] && !LightIntegrals.answers(2 * w, 2 * t, h)) {
            return false;
        }
        wholeX0 = mid - w; wholeX1 = mid + w; wholeY0 = midV - t; wholeY1 = midV + t; wholeH = h;
        wholeA = nx * ax + ny * ay + nz * az;
        wholeB = nx * ux + ny * uy + nz * uz;
        wholeC = nx * vx + ny * vy + nz * vz;
        wholeNx = nx; wholeNy = ny; wholeNz = nz;
        wholeDx = dx; wholeDy = dy; wholeDz = dz;
        pyramid.set(px, py, pz, ax, ay, az, ux, uy, uz, vx, vy, vz, (mid - w) / h, (mid + w) / h,
                (midV - t) / h, (midV + t) / h, h);
        return true;
    }
}

package studio.engine.geometry;

import studio.engine.accel.Aabb;
import studio.engine.math.Fp;
import studio.engine.math.Vec3;

/**
 * A sphere, intersected without catastrophic cancellation (Ray Tracing Gems ch. 7): the
 * discriminant comes from the ray's perpendicular distance to the centre, and the two roots from
 * the numerically stable pair q and c/q. Hit points are re-projected onto the surface.
 */
public record Sphere(Vec3 center, double radius) implements Shape {

    private static final double REPROJECTED_ERROR = Fp.gamma(6);
    private static final double BOUNDS_PADDING = Fp.gamma(8);

    public Sphere {
        if (!center.isFinite()) {
            throw new IllegalArgumentException("sphere centre must be finite: " + center);
        }
        if (!(radius > 0) || !Double.isFinite(radius)) {
            throw new IllegalArgumentException("sphere radius must be positive and finite: " + radius);
        }
    }

    @Override
    public boolean intersect(Ray ray, double tMax, Hit hit) {
        return intersect(center.x(), center.y(), center.z(), radius, ray, tMax, hit);
    }

    @Override
    public boolean occluded(Ray ray, double tMax) {
        return occluded(center.x(), center.y(), center.z(), radius, ray, tMax);
    }

    /** {@inheritDoc} Here: a ball. */
    @Override
    public boolean convex() {
        return true;
    }

    @Override
    public Aabb bounds() {
        double cx = center.x(), cy = center.y(), cz = center.z();
        return new Aabb(cx - radius, cy - radius, cz - radius, cx + radius, cy + radius, cz + radius)
                .padded(BOUNDS_PADDING);
    }

    /**
     * Longitude and latitude as three.js's SphereGeometry lays them out: u = 0 where the surface
     * faces -x, growing towards +z; v = 0 at the bottom pole, 1 at the top. dp/du and dp/dv follow;
     * at a pole dp/du is zero (every longitude meets there).
     */
    @Override
    public void textureCoordinates(Hit hit, TextureCoordinates out) {
        double nx = hit.nx, ny = hit.ny, nz = hit.nz;
        double phi = Math.atan2(nz, -nx);
        double u = phi < 0 ? phi / (2 * Math.PI) + 1 : phi / (2 * Math.PI);
        double v = 1 - Math.acos(Math.max(-1, Math.min(1, ny))) / Math.PI;
        double sinTheta = Math.sqrt(nx * nx + nz * nz);
        double twoPiR = 2 * Math.PI * radius, piR = Math.PI * radius;
        double vx, vy, vz;
        if (sinTheta > 0) {
            vx = -piR * nx * ny / sinTheta;
            vy = piR * sinTheta;
            vz = -piR * nz * ny / sinTheta;
        } else {
            vx = piR;
            vy = 0;
            vz = 0;
        }
        out.set(u >= 1 ? 0 : u, v, twoPiR * nz, 0, -twoPiR * nx, vx, vy, vz, twoPiR, piR, true);
    }

    /**
     * {@link #intersect(Ray, double, Hit)} for the sphere with centre (cx, cy, cz) and the given
     * radius: the one implementation, which the record and a scene's flat sphere arrays both call,
     * so a sphere found either way has the same bits of t, point and normal.
     */
    public static boolean intersect(double cx, double cy, double cz, double radius, Ray ray, double tMax, Hit hit) {
        double t = nearestRoot(cx, cy, cz, radius, ray, tMax);
        if (Double.isNaN(t)) {
            return false;
        }
        double qx = ray.ox + t * ray.dx - cx, qy = ray.oy + t * ray.dy - cy, qz = ray.oz + t * ray.dz - cz;
        double len = Math.sqrt(qx * qx + qy * qy + qz * qz);
        double nx = qx / len, ny = qy / len, nz = qz / len;
        hit.set(t, cx + radius * nx, cy + radius * ny, cz + radius * nz, nx, ny, nz,
                REPROJECTED_ERROR * (Math.abs(cx) + radius),
                REPROJECTED_ERROR * (Math.abs(cy) + radius),
                REPROJECTED_ERROR * (Math.abs(cz) + radius));
        return true;
    }

    /** {@link #occluded(Ray, double)} for the sphere with centre (cx, cy, cz) and the given radius. */
    public static boolean occluded(double cx, double cy, double cz, double radius, Ray ray, double tMax) {
        return !Double.isNaN(nearestRoot(cx, cy, cz, radius, ray, tMax));
    }

    /** The smallest root in (0, tMax), or NaN if there is none. */
    private static double nearestRoot(double cx, double cy, double cz, double radius, Ray ray, double tMax) {
        double fx = ray.ox - cx, fy = ray.oy - cy, fz = ray.oz - cz;
        double dx = ray.dx, dy = ray.dy, dz = ray.dz;
        double a = dx * dx + dy * dy + dz * dz;
        double b = fx * dx + fy * dy + fz * dz;
        double k = b / a;
        double lx = fx - k * dx, ly = fy - k * dy, lz = fz - k * dz;
        double disc = a * (radius * radius - (lx * lx + ly * ly + lz * lz));
        if (!(disc >= 0)) {
            return Double.NaN;
        }
        double q = -b - Math.copySign(Math.sqrt(disc), b);
        double c = fx * fx + fy * fy + fz * fz - radius * radius;
        double t0 = c / q, t1 = q / a;
        if (t0 > t1) {
            double swap = t0; t0 = t1; t1 = swap;
        }
        if (t0 > 0 && t0 < tMax) {
            return t0;
        }
        if (t1 > 0 && t1 < tMax) {
            return t1;
        }
        return Double.NaN;
    }
}

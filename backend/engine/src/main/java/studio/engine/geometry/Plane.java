package studio.engine.geometry;

import studio.engine.accel.Aabb;
import studio.engine.math.Fp;
import studio.engine.math.Vec3;

/** An infinite plane through a point, with a unit normal; rays parallel to it or lying in it miss. */
public record Plane(Vec3 point, Vec3 normal) implements Shape {

    private static final double PARALLEL = 1e-12;
    private static final double POINT_ERROR = Fp.gamma(6);

    public Plane {
        if (!point.isFinite()) {
            throw new IllegalArgumentException("plane point must be finite: " + point);
        }
        if (!normal.isFinite() || normal.length() == 0) {
            throw new IllegalArgumentException("plane normal must be a finite non-zero vector: " + normal);
        }
        normal = normal.normalized();
    }

    @Override
    public boolean intersect(Ray ray, double tMax, Hit hit) {
        double t = distance(ray, tMax);
        if (Double.isNaN(t)) {
            return false;
        }
        double tdx = t * ray.dx, tdy = t * ray.dy, tdz = t * ray.dz;
        hit.set(t, ray.ox + tdx, ray.oy + tdy, ray.oz + tdz, normal.x(), normal.y(), normal.z(),
                POINT_ERROR * (Math.abs(ray.ox) + Math.abs(tdx) + Math.abs(point.x())),
                POINT_ERROR * (Math.abs(ray.oy) + Math.abs(tdy) + Math.abs(point.y())),
                POINT_ERROR * (Math.abs(ray.oz) + Math.abs(tdz) + Math.abs(point.z())));
        return true;
    }

    @Override
    public boolean occluded(Ray ray, double tMax) {
        return !Double.isNaN(distance(ray, tMax));
    }

    /** {@inheritDoc} Here: a plane. */
    @Override
    public boolean convex() {
        return true;
    }

    /** Unbounded: planes are tested beside a BVH, never in it. */
    @Override
    public Aabb bounds() {
        return Aabb.UNBOUNDED;
    }

    /**
     * World units along a tangent frame that depends on the normal alone (Duff et al., "Building an
     * Orthonormal Basis, Revisited", JCGT 2017), measured from the plane's point: on a floor (normal
     * +y) u runs along +x and v along -z, as three.js lays a PlaneGeometry turned to the floor.
     */
    @Override
    public void textureCoordinates(Hit hit, TextureCoordinates out) {
        double nx = normal.x(), ny = normal.y(), nz = normal.z();
        double sign = Math.copySign(1.0, nz);
        double a = -1 / (sign + nz);
        double b = nx * ny * a;
        double tx = 1 + sign * nx * nx * a, ty = sign * b, tz = -sign * nx;
        double bx = b, by = sign + ny * ny * a, bz = -ny;
        double rx = hit.px - point.x(), ry = hit.py - point.y(), rz = hit.pz - point.z();
        out.set(rx * tx + ry * ty + rz * tz, rx * bx + ry * by + rz * bz, tx, ty, tz, bx, by, bz, 1, 1, false);
    }

    private double distance(Ray ray, double tMax) {
        double nx = normal.x(), ny = normal.y(), nz = normal.z();
        double denom = nx * ray.dx + ny * ray.dy + nz * ray.dz;
        double dLen = Math.sqrt(ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz);
        if (!(Math.abs(denom) > PARALLEL * dLen)) {
            return Double.NaN;
        }
        double t = (nx * (point.x() - ray.ox) + ny * (point.y() - ray.oy) + nz * (point.z() - ray.oz)) / denom;
        return t > 0 && t < tMax && Double.isFinite(t) ? t : Double.NaN;
    }
}

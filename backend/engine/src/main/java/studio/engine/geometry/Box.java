package studio.engine.geometry;

import studio.engine.accel.Aabb;
import studio.engine.math.Fp;
import studio.engine.math.Rotation;
import studio.engine.math.Vec3;

/**
 * A box given by its centre, its full size along its own axes and a rotation (Euler degrees,
 * order XYZ as three.js). The ray is taken into the box's frame and clipped against three slabs
 * with the robust slab test: a zero direction component is handled without 0*inf, the comparison
 * is non-strict and the far distances are widened by 1 + 2*gamma(3) (Williams et al.; Ize).
 * Hit points are re-projected exactly onto the face they lie on.
 */
public final class Box implements Shape {

    private static final double FAR_WIDENING = 1 + 2 * Fp.gamma(3);
    private static final double POINT_ERROR = Fp.gamma(12);
    private static final double BOUNDS_PADDING = Fp.gamma(16);

    private final Vec3 center, size, rotationDegrees;
    private final double cx, cy, cz, hx, hy, hz;
    /** World-from-box rotation, row major. */
    private final double m00, m01, m02, m10, m11, m12, m20, m21, m22;
    /**
     * Whether the rotation is exactly none, so the ray needs no turning into the box's frame: the
     * same numbers as turning it by the identity (1 * x + 0 * y + 0 * z is x, but for the sign of
     * a zero, which no result of the test depends on).
     */
    private final boolean axisAligned;

    public Box(Vec3 center, Vec3 size, Vec3 rotationDegrees) {
        if (!center.isFinite()) {
            throw new IllegalArgumentException("box centre must be finite: " + center);
        }
        if (!size.isFinite() || !(size.x() > 0) || !(size.y() > 0) || !(size.z() > 0)) {
            throw new IllegalArgumentException("box size must be positive and finite on every axis: " + size);
        }
        if (!rotationDegrees.isFinite()) {
            throw new IllegalArgumentException("box rotation must be finite: " + rotationDegrees);
        }
        this.center = center;
        this.size = size;
        this.rotationDegrees = rotationDegrees;
        cx = center.x(); cy = center.y(); cz = center.z();
        hx = size.x() / 2; hy = size.y() / 2; hz = size.z() / 2;
        Rotation r = Rotation.fromEulerDegrees(rotationDegrees);
        m00 = r.get(0, 0); m01 = r.get(0, 1); m02 = r.get(0, 2);
        m10 = r.get(1, 0); m11 = r.get(1, 1); m12 = r.get(1, 2);
        m20 = r.get(2, 0); m21 = r.get(2, 1); m22 = r.get(2, 2);
        axisAligned = m00 == 1 && m11 == 1 && m22 == 1
                && m01 == 0 && m02 == 0 && m10 == 0 && m12 == 0 && m20 == 0 && m21 == 0;
    }

    public Box(Vec3 center, Vec3 size) {
        this(center, size, Vec3.ZERO);
    }

    public Vec3 center() {
        return center;
    }

    public Vec3 size() {
        return size;
    }

    public Vec3 rotationDegrees() {
        return rotationDegrees;
    }

    @Override
    public boolean intersect(Ray ray, double tMax, Hit hit) {
        double px = ray.ox - cx, py = ray.oy - cy, pz = ray.oz - cz;
        double ox, oy, oz, dx, dy, dz;
        if (axisAligned) {
            ox = px; oy = py; oz = pz;
            dx = ray.dx; dy = ray.dy; dz = ray.dz;
        } else {
            ox = m00 * px + m10 * py + m20 * pz;
            oy = m01 * px + m11 * py + m21 * pz;
            oz = m02 * px + m12 * py + m22 * pz;
            dx = m00 * ray.dx + m10 * ray.dy + m20 * ray.dz;
            dy = m01 * ray.dx + m11 * ray.dy + m21 * ray.dz;
            dz = m02 * ray.dx + m12 * ray.dy + m22 * ray.dz;
        }

        double tNear = Double.NEGATIVE_INFINITY, tFar = Double.POSITIVE_INFINITY;
        int nearAxis = -1, farAxis = -1;
        for (int axis = 0; axis < 3; axis++) {
            double o = axis == 0 ? ox : axis == 1 ? oy : oz;
            double d = axis == 0 ? dx : axis == 1 ? dy : dz;
            double h = axis == 0 ? hx : axis == 1 ? hy : hz;
            if (d == 0) {
                if (o < -h || o > h) {
                    return false;
                }
                continue;
            }
            double inv = 1 / d;
            double t0 = (-h - o) * inv, t1 = (h - o) * inv;
            if (t0 > t1) {
                double s = t0; t0 = t1; t1 = s;
            }
            t1 *= FAR_WIDENING;
            if (t0 > tNear) {
                tNear = t0;
                nearAxis = axis;
            }
            if (t1 < tFar) {
                tFar = t1;
                farAxis = axis;
            }
        }
        if (tNear > tFar) {
            return false;
        }
        double t;
        int axis;
        double sign;
        if (tNear > 0) {
            t = tNear;
            axis = nearAxis;
            sign = -Math.signum(axis == 0 ? dx : axis == 1 ? dy : dz);
        } else {
            // The ray starts inside (or on) the box: it leaves through the far face.
            t = tFar;
            axis = farAxis;
            sign = Math.signum(axis == 0 ? dx : axis == 1 ? dy : dz);
        }
        if (!(t > 0 && t < tMax)) {
            return false;
        }
        double lx = clamp(ox + t * dx, hx), ly = clamp(oy + t * dy, hy), lz = clamp(oz + t * dz, hz);
        if (axis == 0) {
            lx = sign * hx;
        } else if (axis == 1) {
            ly = sign * hy;
        } else {
            lz = sign * hz;
        }
        double wx = cx + m00 * lx + m01 * ly + m02 * lz;
        double wy = cy + m10 * lx + m11 * ly + m12 * lz;
        double wz = cz + m20 * lx + m21 * ly + m22 * lz;
        double nx, ny, nz;
        if (axis == 0) {
            nx = sign * m00; ny = sign * m10; nz = sign * m20;
        } else if (axis == 1) {
            nx = sign * m01; ny = sign * m11; nz = sign * m21;
        } else {
            nx = sign * m02; ny = sign * m12; nz = sign * m22;
        }
        double extent = Math.abs(lx) + Math.abs(ly) + Math.abs(lz);
        hit.set(t, wx, wy, wz, nx, ny, nz,
                POINT_ERROR * (Math.abs(cx) + extent),
                POINT_ERROR * (Math.abs(cy) + extent),
                POINT_ERROR * (Math.abs(cz) + extent));
        return true;
    }

    @Override
    public boolean occluded(Ray ray, double tMax) {
        double px = ray.ox - cx, py = ray.oy - cy, pz = ray.oz - cz;
        double tNear = Double.NEGATIVE_INFINITY, tFar = Double.POSITIVE_INFINITY;
        for (int axis = 0; axis < 3; axis++) {
            double ax, ay, az, h;
            if (axis == 0) {
                ax = m00; ay = m10; az = m20; h = hx;
            } else if (axis == 1) {
                ax = m01; ay = m11; az = m21; h = hy;
            } else {
                ax = m02; ay = m12; az = m22; h = hz;
            }
            double o, d;
            if (axisAligned) {
                o = axis == 0 ? px : axis == 1 ? py : pz;
                d = axis == 0 ? ray.dx : axis == 1 ? ray.dy : ray.dz;
            } else {
                o = ax * px + ay * py + az * pz;
                d = ax * ray.dx + ay * ray.dy + az * ray.dz;
            }
            if (d == 0) {
                if (o < -h || o > h) {
                    return false;
                }
                continue;
            }
            double inv = 1 / d;
            double t0 = (-h - o) * inv, t1 = (h - o) * inv;
            if (t0 > t1) {
                double s = t0; t0 = t1; t1 = s;
            }
            tNear = Math.max(tNear, t0);
            tFar = Math.min(tFar, t1 * FAR_WIDENING);
        }
        if (tNear > tFar) {
            return false;
        }
        double t = tNear > 0 ? tNear : tFar;
        return t > 0 && t < tMax;
    }

    /** {@inheritDoc} Here: a box, rotated or not. */
    @Override
    public boolean convex() {
        return true;
    }

    /** The rotated box's world-space extent: the centre plus or minus |R| times the half size. */
    @Override
    public Aabb bounds() {
        double ex = Math.abs(m00) * hx + Math.abs(m01) * hy + Math.abs(m02) * hz;
        double ey = Math.abs(m10) * hx + Math.abs(m11) * hy + Math.abs(m12) * hz;
        double ez = Math.abs(m20) * hx + Math.abs(m21) * hy + Math.abs(m22) * hz;
        return new Aabb(cx - ex, cy - ey, cz - ez, cx + ex, cy + ey, cz + ez).padded(BOUNDS_PADDING);
    }

    /**
     * Each face 0..1, seen from outside with u to the right and v up (the top and bottom faces with
     * -z and +z up): the hit point taken into the box's frame, its face the axis it lies furthest
     * out along, relative to the half size.
     */
    @Override
    public void textureCoordinates(Hit hit, TextureCoordinates out) {
        double px = hit.px - cx, py = hit.py - cy, pz = hit.pz - cz;
        double lx = m00 * px + m10 * py + m20 * pz;
        double ly = m01 * px + m11 * py + m21 * pz;
        double lz = m02 * px + m12 * py + m22 * pz;
        double fx = Math.abs(lx) / hx, fy = Math.abs(ly) / hy, fz = Math.abs(lz) / hz;
        int uAxis, vAxis;
        double uSign, vSign;
        if (fx >= fy && fx >= fz) {
            uAxis = 2; vAxis = 1;
            uSign = lx >= 0 ? -1 : 1; vSign = 1;
        } else if (fy >= fz) {
            uAxis = 0; vAxis = 2;
            uSign = 1; vSign = ly >= 0 ? -1 : 1;
        } else {
            uAxis = 0; vAxis = 1;
            uSign = lz >= 0 ? 1 : -1; vSign = 1;
        }
        double hu = uAxis == 0 ? hx : hz, hv = vAxis == 1 ? hy : hz;
        double lu = uAxis == 0 ? lx : lz, lv = vAxis == 1 ? ly : lz;
        double su = uSign * 2 * hu, sv = vSign * 2 * hv;
        out.set((uSign * lu / hu + 1) / 2, (vSign * lv / hv + 1) / 2,
                su * column(uAxis, 0), su * column(uAxis, 1), su * column(uAxis, 2),
                sv * column(vAxis, 0), sv * column(vAxis, 1), sv * column(vAxis, 2), 2 * hu, 2 * hv, false);
    }

    /** Row {@code row} of the world-from-box rotation's column {@code axis}: the box's axis in the world. */
    private double column(int axis, int row) {
        return switch (row * 3 + axis) {
            case 0 -> m00; case 1 -> m01; case 2 -> m02;
            case 3 -> m10; case 4 -> m11; case 5 -> m12;
            case 6 -> m20; case 7 -> m21; default -> m22;
        };
    }

    private static double clamp(double v, double h) {
        return v < -h ? -h : v > h ? h : v;
    }

    /** The same centre, size and rotation, to the bit: the same box (everything else is worked out from them). */
    @Override
    public boolean equals(Object other) {
        return other instanceof Box b && center.equals(b.center) && size.equals(b.size)
                && rotationDegrees.equals(b.rotationDegrees);
    }

    @Override
    public int hashCode() {
        return java.util.Objects.hash(center, size, rotationDegrees);
    }

    @Override
    public String toString() {
        return "Box[center=" + center + ", size=" + size + ", rotationDegrees=" + rotationDegrees + "]";
    }
}

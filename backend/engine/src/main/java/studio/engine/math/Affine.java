package studio.engine.math;

import java.util.Arrays;

/**
 * An affine map of space, {@code p -> M p + t}: a 3x3 linear part and a translation, as the rows of a
 * 3x4 matrix. Models placed by nested transforms (glTF's node hierarchy: translation, rotation as a
 * unit quaternion, scale along each axis, or a whole matrix) compose these and apply the result to
 * their vertices once, before a mesh is built; rays are never transformed. Normals go through the
 * inverse transpose of the linear part, so a non-uniform scale keeps them perpendicular to the surface.
 */
public final class Affine {

    public static final Affine IDENTITY = new Affine(new double[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0});

    /** Row-major 3x4: m[4 * row + col], column 3 is the translation. */
    private final double[] m;

    private Affine(double[] m) {
        this.m = m;
    }

    /**
     * From a 4x4 matrix in column-major order (as glTF and three.js store one); its last row must be
     * (0, 0, 0, 1).
     *
     * @throws IllegalArgumentException if it has not 16 finite values or is not affine
     */
    public static Affine fromColumnMajor(double[] c) {
        if (c == null || c.length != 16) {
            throw new IllegalArgumentException("a matrix has 16 values");
        }
        for (double v : c) {
            if (!Double.isFinite(v)) {
                throw new IllegalArgumentException("a matrix's values must be finite: " + v);
            }
        }
        if (c[3] != 0 || c[7] != 0 || c[11] != 0 || c[15] != 1) {
            throw new IllegalArgumentException("the matrix's last row must be (0, 0, 0, 1), not a projection");
        }
        double[] m = new double[12];
        for (int row = 0; row < 3; row++) {
            for (int col = 0; col < 4; col++) {
                m[4 * row + col] = c[4 * col + row];
            }
        }
        return new Affine(m);
    }

    /**
     * Scale, then rotate by the quaternion (x, y, z, w; normalised here), then translate: T * R * S,
     * as glTF composes a node's TRS.
     *
     * @throws IllegalArgumentException if a value is not finite or the quaternion is zero
     */
    public static Affine trs(Vec3 translation, double qx, double qy, double qz, double qw, Vec3 scale) {
        double n = Math.sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
        if (!(n > 0) || !Double.isFinite(n) || !translation.isFinite() || !scale.isFinite()) {
            throw new IllegalArgumentException("translation, rotation and scale must be finite, the rotation non-zero");
        }
        double x = qx / n, y = qy / n, z = qz / n, w = qw / n;
        double[] r = {
            1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
            2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
            2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)};
        double[] s = {scale.x(), scale.y(), scale.z()};
        double[] t = {translation.x(), translation.y(), translation.z()};
        double[] m = new double[12];
        for (int row = 0; row < 3; row++) {
            for (int col = 0; col < 3; col++) {
                m[4 * row + col] = r[3 * row + col] * s[col];
            }
            m[4 * row + 3] = t[row];
        }
        return new Affine(m);
    }

    /** This map after {@code inner}: {@code p -> this(inner(p))}. */
    public Affine times(Affine inner) {
        double[] a = m, b = inner.m;
        double[] r = new double[12];
        for (int row = 0; row < 3; row++) {
            for (int col = 0; col < 4; col++) {
                double v = a[4 * row] * b[col] + a[4 * row + 1] * b[4 + col] + a[4 * row + 2] * b[8 + col];
                r[4 * row + col] = col == 3 ? v + a[4 * row + 3] : v;
            }
        }
        return new Affine(r);
    }

    /** The determinant of the linear part: negative for a map that mirrors (and so turns triangles' winding). */
    public double determinant() {
        return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8])
                + m[2] * (m[4] * m[9] - m[5] * m[8]);
    }

    public Vec3 applyToPoint(Vec3 p) {
        return new Vec3(m[0] * p.x() + m[1] * p.y() + m[2] * p.z() + m[3],
                m[4] * p.x() + m[5] * p.y() + m[6] * p.z() + m[7],
                m[8] * p.x() + m[9] * p.y() + m[10] * p.z() + m[11]);
    }

    /** Maps {@code count} points (x, y, z each) from {@code from} into {@code to} at {@code at} (in values). */
    public void applyToPoints(double[] from, int count, double[] to, int at) {
        for (int i = 0; i < count; i++) {
            double x = from[3 * i], y = from[3 * i + 1], z = from[3 * i + 2];
            to[at + 3 * i] = m[0] * x + m[1] * y + m[2] * z + m[3];
            to[at + 3 * i + 1] = m[4] * x + m[5] * y + m[6] * z + m[7];
            to[at + 3 * i + 2] = m[8] * x + m[9] * y + m[10] * z + m[11];
        }
    }

    /**
     * Maps {@code count} normals through the inverse transpose of the linear part (its cofactor matrix,
     * which is the same up to a positive factor when the determinant is positive, and is turned for a
     * negative one), unit length; a normal that maps to zero (a singular map) stays as it was.
     */
    public void applyToNormals(double[] from, int count, double[] to, int at) {
        double a = m[0], b = m[1], c = m[2], d = m[4], e = m[5], f = m[6], g = m[8], h = m[9], k = m[10];
        double sign = determinant() < 0 ? -1 : 1;
        double c00 = sign * (e * k - f * h), c01 = sign * (f * g - d * k), c02 = sign * (d * h - e * g);
        double c10 = sign * (c * h - b * k), c11 = sign * (a * k - c * g), c12 = sign * (b * g - a * h);
        double c20 = sign * (b * f - c * e), c21 = sign * (c * d - a * f), c22 = sign * (a * e - b * d);
        for (int i = 0; i < count; i++) {
            double x = from[3 * i], y = from[3 * i + 1], z = from[3 * i + 2];
            double nx = c00 * x + c01 * y + c02 * z, ny = c10 * x + c11 * y + c12 * z, nz = c20 * x + c21 * y + c22 * z;
            double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
            if (length > 0 && Double.isFinite(length)) {
                to[at + 3 * i] = nx / length;
                to[at + 3 * i + 1] = ny / length;
                to[at + 3 * i + 2] = nz / length;
            } else {
                to[at + 3 * i] = x;
                to[at + 3 * i + 1] = y;
                to[at + 3 * i + 2] = z;
            }
        }
    }

    public boolean isFinite() {
        for (double v : m) {
            if (!Double.isFinite(v)) {
                return false;
            }
        }
        return true;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Affine a && Arrays.equals(m, a.m);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(m);
    }

    @Override
    public String toString() {
        return "Affine" + Arrays.toString(m);
    }
}

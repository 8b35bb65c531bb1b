package studio.engine.math;

/**
 * A rotation matrix from Euler angles in degrees about x, y and z, applied in three.js's
 * default order 'XYZ' (matrix = Rx * Ry * Rz), so the editor's preview and the render agree.
 */
public final class Rotation {

    private final double m00, m01, m02, m10, m11, m12, m20, m21, m22;

    private Rotation(double m00, double m01, double m02, double m10, double m11, double m12,
                     double m20, double m21, double m22) {
        this.m00 = m00; this.m01 = m01; this.m02 = m02;
        this.m10 = m10; this.m11 = m11; this.m12 = m12;
        this.m20 = m20; this.m21 = m21; this.m22 = m22;
    }

    public static Rotation fromEulerDegrees(Vec3 degrees) {
        double cx = cosDegrees(degrees.x()), sx = sinDegrees(degrees.x());
        double cy = cosDegrees(degrees.y()), sy = sinDegrees(degrees.y());
        double cz = cosDegrees(degrees.z()), sz = sinDegrees(degrees.z());
        // Rx * Ry * Rz, written out (three.js Matrix4.makeRotationFromEuler, order XYZ)
        return new Rotation(
                cy * cz, -cy * sz, sy,
                cx * sz + sx * sy * cz, cx * cz - sx * sy * sz, -sx * cy,
                sx * sz - cx * sy * cz, sx * cz + cx * sy * sz, cx * cy);
    }

    /** Sine of an angle in degrees, exact at multiples of 90 degrees. */
    static double sinDegrees(double deg) {
        double r = deg % 360;
        if (r % 90 == 0) {
            int q = (int) Math.round(r / 90);
            return switch (Math.floorMod(q, 4)) { case 1 -> 1; case 3 -> -1; default -> 0; };
        }
        return Math.sin(Math.toRadians(r));
    }

    static double cosDegrees(double deg) {
        return sinDegrees(deg + 90);
    }

    /** This matrix times v: object space to world space. */
    public Vec3 apply(Vec3 v) {
        return new Vec3(m00 * v.x() + m01 * v.y() + m02 * v.z(),
                m10 * v.x() + m11 * v.y() + m12 * v.z(),
                m20 * v.x() + m21 * v.y() + m22 * v.z());
    }

    /** Element (row, column). */
    public double get(int row, int col) {
        return switch (row * 3 + col) {
            case 0 -> m00; case 1 -> m01; case 2 -> m02;
            case 3 -> m10; case 4 -> m11; case 5 -> m12;
            case 6 -> m20; case 7 -> m21; default -> m22;
        };
    }
}

package studio.engine.math;

/** An immutable 3-vector of doubles: points, directions and normals in setup and shading code. */
public record Vec3(double x, double y, double z) {

    public static final Vec3 ZERO = new Vec3(0, 0, 0);

    public Vec3 plus(Vec3 o) {
        return new Vec3(x + o.x, y + o.y, z + o.z);
    }

    public Vec3 minus(Vec3 o) {
        return new Vec3(x - o.x, y - o.y, z - o.z);
    }

    public Vec3 times(double s) {
        return new Vec3(x * s, y * s, z * s);
    }

    public Vec3 negated() {
        return new Vec3(-x, -y, -z);
    }

    public double dot(Vec3 o) {
        return x * o.x + y * o.y + z * o.z;
    }

    public Vec3 cross(Vec3 o) {
        return new Vec3(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x);
    }

    public double lengthSquared() {
        return x * x + y * y + z * z;
    }

    /** Euclidean length without overflow or underflow for very large or small components. */
    public double length() {
        double m = Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
        if (m == 0 || !Double.isFinite(m)) {
            return m;
        }
        double a = x / m, b = y / m, c = z / m;
        return m * Math.sqrt(a * a + b * b + c * c);
    }

    /** This vector scaled to unit length; throws if it has no direction. */
    public Vec3 normalized() {
        double len = length();
        if (!(len > 0) || !Double.isFinite(len)) {
            throw new IllegalArgumentException("cannot normalise a zero-length or non-finite vector " + this);
        }
        return new Vec3(x / len, y / len, z / len);
    }

    public boolean isFinite() {
        return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
    }

    public double get(int axis) {
        return axis == 0 ? x : axis == 1 ? y : z;
    }
}

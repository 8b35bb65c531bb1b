package studio.engine.camera;

import java.util.Arrays;

import studio.engine.geometry.Frustum;
import studio.engine.geometry.Ray;
import studio.engine.math.Vec3;

/**
 * A perspective camera from position, target, up and vertical field of view (as three.js's
 * PerspectiveCamera). Directions are built in camera space, -w + x*u + y*v, and never by adding
 * and subtracting world positions, so a camera far from the origin keeps every pixel distinct.
 */
public final class Camera {

    /** |up x w| below this fraction of |up| counts as parallel. */
    private static final double PARALLEL = 1e-9;

    private final Vec3 position;
    private final double px, py, pz, ux, uy, uz, vx, vy, vz, wx, wy, wz;
    private final double tanHalfFov;

    public Camera(Vec3 position, Vec3 lookAt, Vec3 up, double fovDegrees) {
        if (!position.isFinite() || !lookAt.isFinite() || !up.isFinite()) {
            throw new IllegalArgumentException("camera position, lookAt and up must be finite");
        }
        if (!(fovDegrees > 0 && fovDegrees < 180)) {
            throw new IllegalArgumentException("camera fov must be between 0 and 180 degrees (exclusive): " + fovDegrees);
        }
        Vec3 back = position.minus(lookAt);
        if (back.length() == 0) {
            throw new IllegalArgumentException("camera lookAt must differ from its position");
        }
        double upLength = up.length();
        if (upLength == 0) {
            throw new IllegalArgumentException("camera up must not be a zero vector");
        }
        Vec3 w = back.normalized();
        Vec3 side = up.cross(w);
        if (side.length() <= PARALLEL * upLength) {
            throw new IllegalArgumentException("camera up is parallel to the view direction; choose an up vector "
                    + "that is not along lookAt - position");
        }
        Vec3 u = side.normalized();
        Vec3 v = w.cross(u);
        this.position = position;
        px = position.x(); py = position.y(); pz = position.z();
        ux = u.x(); uy = u.y(); uz = u.z();
        vx = v.x(); vy = v.y(); vz = v.z();
        wx = w.x(); wy = w.y(); wz = w.z();
        tanHalfFov = Math.tan(Math.toRadians(fovDegrees) / 2);
    }

    /**
     * The primary ray through a point of the image plane given in normalised device coordinates:
     * {@code ndcX} from -1 (left edge) to 1 (right), {@code ndcY} from -1 (bottom) to 1 (top);
     * {@code aspect} is width / height. The direction has unit length.
     */
    public Ray ray(double ndcX, double ndcY, double aspect) {
        return ray(ndcX, ndcY, aspect, new Ray());
    }

    /** {@link #ray(double, double, double)} into {@code out} (the hot loop reuses one); returns out. */
    public Ray ray(double ndcX, double ndcY, double aspect, Ray out) {
        double x = ndcX * tanHalfFov * aspect, y = ndcY * tanHalfFov;
        double dx = x * ux + y * vx - wx, dy = x * uy + y * vy - wy, dz = x * uz + y * vz - wz;
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        return out.set(px, py, pz, dx / len, dy / len, dz / len);
    }

    /**
     * Into {@code out}: a pyramid holding every ray {@link #ray(double, double, double, Ray)}
     * shoots through normalised device coordinates between ndcX0 and ndcX1 and between ndcY0 and
     * ndcY1 (inclusive), for this aspect. Returns out.
     */
    public Frustum frustum(double ndcX0, double ndcX1, double ndcY0, double ndcY1, double aspect, Frustum out) {
        double scaleX = tanHalfFov * aspect;
        return out.set(px, py, pz, -wx, -wy, -wz, ux, uy, uz, vx, vy, vz,
                ndcX0 * scaleX, ndcX1 * scaleX, ndcY0 * tanHalfFov, ndcY1 * tanHalfFov, Double.POSITIVE_INFINITY);
    }

    public Vec3 position() {
        return position;
    }

    /**
     * The angle (radians, small-angle) between the rays through neighbouring pixels of an image
     * {@code height} pixels high, at its centre: the spread of a pixel's ray cone.
     */
    public double pixelSpread(int height) {
        return 2 * tanHalfFov / height;
    }

    /** Unit vectors of the camera frame: right, up and backwards (away from the target). */
    public Vec3 right() {
        return new Vec3(ux, uy, uz);
    }

    public Vec3 upward() {
        return new Vec3(vx, vy, vz);
    }

    public Vec3 backward() {
        return new Vec3(wx, wy, wz);
    }

    /** The same position, frame and field of view, to the bit: every pixel's ray is the same. */
    @Override
    public boolean equals(Object other) {
        return other instanceof Camera c && position.equals(c.position)
                && Arrays.equals(frame(), c.frame());
    }

    @Override
    public int hashCode() {
        return 31 * position.hashCode() + Arrays.hashCode(frame());
    }

    private double[] frame() {
        return new double[] {ux, uy, uz, vx, vy, vz, wx, wy, wz, tanHalfFov};
    }
}

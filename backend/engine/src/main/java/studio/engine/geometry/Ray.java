package studio.engine.geometry;

import studio.engine.math.Vec3;

/** A ray o + t*d. The direction need not be unit length; intersection tests accept any non-zero d. */
public final class Ray {

    public final double ox, oy, oz;
    public final double dx, dy, dz;

    public Ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        this.ox = ox; this.oy = oy; this.oz = oz;
        this.dx = dx; this.dy = dy; this.dz = dz;
    }

    public Ray(Vec3 origin, Vec3 direction) {
        this(origin.x(), origin.y(), origin.z(), direction.x(), direction.y(), direction.z());
    }

    public Vec3 origin() {
        return new Vec3(ox, oy, oz);
    }

    public Vec3 direction() {
        return new Vec3(dx, dy, dz);
    }

    @Override
    public String toString() {
        return "Ray[o=(" + ox + ", " + oy + ", " + oz + "), d=(" + dx + ", " + dy + ", " + dz + ")]";
    }
}

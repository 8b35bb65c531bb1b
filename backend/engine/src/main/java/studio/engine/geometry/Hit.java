package studio.engine.geometry;

import studio.engine.math.Vec3;

/**
 * The nearest intersection found so far: distance, point, outward geometric normal (unit length)
 * and a conservative per-component bound on the point's rounding error. Mutable and reused: one
 * per worker thread and recursion depth.
 */
public final class Hit {

    public double t;
    public double px, py, pz;
    public double nx, ny, nz;
    /** Absolute error bound of each component of the hit point. */
    public double ex, ey, ez;
    /** Index of the primitive in its scene, in declaration order. */
    public int primitive;

    void set(double t, double px, double py, double pz, double nx, double ny, double nz,
             double ex, double ey, double ez) {
        this.t = t;
        this.px = px; this.py = py; this.pz = pz;
        this.nx = nx; this.ny = ny; this.nz = nz;
        this.ex = ex; this.ey = ey; this.ez = ez;
    }

    public Vec3 point() {
        return new Vec3(px, py, pz);
    }

    public Vec3 normal() {
        return new Vec3(nx, ny, nz);
    }
}

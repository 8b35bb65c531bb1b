package studio.engine.geometry;

/**
 * A ray in the frame of the watertight ray/triangle test (Woop, Benthin and Wald, JCGT 2013): the
 * axes permuted so that the direction's largest component becomes z (kx, ky swapped when it is
 * negative, so the winding is kept), the shear (sx, sy, sz) that makes the ray run along z, and the
 * origin's permuted coordinates. Worked out once per ray, however many meshes and triangles the ray
 * then meets ({@link Ray#shear}). Read-only outside this class.
 */
public final class RayShear {

    public int kx, ky, kz;
    public double sx, sy, sz;
    public double okx, oky, okz;

    /** Sets this up for the ray. */
    void setUp(Ray ray) {
        double dx = ray.dx, dy = ray.dy, dz = ray.dz;
        double ax = Math.abs(dx), ay = Math.abs(dy), az = Math.abs(dz);
        int z = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        int x = z == 2 ? 0 : z + 1;
        int y = x == 2 ? 0 : x + 1;
        double dkz = component(z, dx, dy, dz);
        if (dkz < 0) {
            int swap = x;
            x = y;
            y = swap;
        }
        kx = x;
        ky = y;
        kz = z;
        sz = 1 / dkz;
        sx = -component(x, dx, dy, dz) * sz;
        sy = -component(y, dx, dy, dz) * sz;
        okx = component(x, ray.ox, ray.oy, ray.oz);
        oky = component(y, ray.ox, ray.oy, ray.oz);
        okz = component(z, ray.ox, ray.oy, ray.oz);
    }

    private static double component(int axis, double x, double y, double z) {
        return axis == 0 ? x : axis == 1 ? y : z;
    }
}

package studio.engine.accel;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.RayShear;
import studio.engine.math.Fp;

/**
 * A mesh's triangles at the leaf slots of its tree (slot = triangle, its vertex indices at
 * {@code indices[3 slot ..]}), met with the watertight test of Woop, Benthin and Wald (JCGT 2013):
 * the axes are permuted so the ray's largest direction component becomes z, the triangle is
 * sheared so the ray runs along z, and the three edge functions decide ({@link Ray#shear}, worked
 * out once per ray). An edge shared by two triangles gives each exactly the negated edge function,
 * and edge functions of zero count as inside for both, so no ray slips through a shared edge
 * (robustness case NUM-08, docs/robustness.md). As in pbrt, a hit counts only if t exceeds its own
 * rounding bound.
 *
 * <p>A closest-hit walk keeps its best triangle in {@code hit.triangle} and its distance as the
 * cull distance; the mesh fills the rest of the hit once, for the winner.
 */
public final class TriangleLeaves implements Leaves {

    private static final double G2 = Fp.gamma(2), G3 = Fp.gamma(3), G5 = Fp.gamma(5);

    private final double[] positions;
    private final int[] indices;

    /** Triangles {@code indices[3t .. 3t+2]} over {@code positions} (3 per vertex); kept, not copied. */
    public TriangleLeaves(double[] positions, int[] indices) {
        this.positions = positions;
        this.indices = indices;
    }

    @Override
    public double nearest(int first, int end, Ray ray, double tMax, double cull, Hit hit) {
        RayShear f = ray.shear();
        int kx = f.kx, ky = f.ky, kz = f.kz;
        double okx = f.okx, oky = f.oky, okz = f.okz, sx = f.sx, sy = f.sy, sz = f.sz;
        for (int tri = first; tri < end; tri++) {
            double t = distance(tri, okx, oky, okz, kx, ky, kz, sx, sy, sz, cull);
            if (t == t) {
                cull = t;
                hit.triangle = tri;
            }
        }
        return cull;
    }

    @Override
    public boolean any(int first, int end, Ray ray, double tMax) {
        RayShear f = ray.shear();
        int kx = f.kx, ky = f.ky, kz = f.kz;
        double okx = f.okx, oky = f.oky, okz = f.okz, sx = f.sx, sy = f.sy, sz = f.sz;
        for (int tri = first; tri < end; tri++) {
            double t = distance(tri, okx, oky, okz, kx, ky, kz, sx, sy, sz, tMax);
            if (t == t) {
                return true;
            }
        }
        return false;
    }

    /**
     * The watertight test of triangle {@code tri} against the permuted and sheared ray: its
     * distance if 0 &lt; t &lt; tMax and t exceeds its rounding bound, else NaN.
     */
    public double distance(int tri, RayShear f, double tMax) {
        return distance(tri, f.okx, f.oky, f.okz, f.kx, f.ky, f.kz, f.sx, f.sy, f.sz, tMax);
    }

    /** {@link #distance(int, RayShear, double)} with the sheared ray's values in locals, loaded once a leaf. */
    private double distance(int tri, double okx, double oky, double okz, int kx, int ky, int kz,
                            double sx, double sy, double sz, double tMax) {
        double[] p = positions;
        int a = 3 * indices[3 * tri], b = 3 * indices[3 * tri + 1], c = 3 * indices[3 * tri + 2];
        double z0 = p[a + kz] - okz, z1 = p[b + kz] - okz, z2 = p[c + kz] - okz;
        double x0 = p[a + kx] - okx + sx * z0, y0 = p[a + ky] - oky + sy * z0;
        double x1 = p[b + kx] - okx + sx * z1, y1 = p[b + ky] - oky + sy * z1;
        double x2 = p[c + kx] - okx + sx * z2, y2 = p[c + ky] - oky + sy * z2;
        double e0 = x1 * y2 - y1 * x2, e1 = x2 * y0 - y2 * x0, e2 = x0 * y1 - y0 * x1;
        if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) {
            return Double.NaN;
        }
        double det = e0 + e1 + e2;
        if (det == 0) {
            return Double.NaN;
        }
        z0 *= sz;
        z1 *= sz;
        z2 *= sz;
        double tScaled = e0 * z0 + e1 * z1 + e2 * z2;
        if (det < 0 ? tScaled >= 0 || tScaled < tMax * det : tScaled <= 0 || tScaled > tMax * det) {
            return Double.NaN;
        }
        double invDet = 1 / det;
        double t = tScaled * invDet;
        if (!(t > 0 && t < tMax)) {
            return Double.NaN;
        }
        // pbrt-v3 3.9.6: t must exceed the bound on its own rounding error.
        double maxZ = Math.max(Math.abs(z0), Math.max(Math.abs(z1), Math.abs(z2)));
        double maxX = Math.max(Math.abs(x0), Math.max(Math.abs(x1), Math.abs(x2)));
        double maxY = Math.max(Math.abs(y0), Math.max(Math.abs(y1), Math.abs(y2)));
        double deltaX = G5 * (maxX + maxZ), deltaY = G5 * (maxY + maxZ), deltaZ = G3 * maxZ;
        double deltaE = 2 * (G2 * maxX * maxY + deltaY * maxX + deltaX * maxY);
        double maxE = Math.max(Math.abs(e0), Math.max(Math.abs(e1), Math.abs(e2)));
        double deltaT = 3 * (G3 * maxE * maxZ + deltaE * maxZ + deltaZ * maxE) * Math.abs(invDet);
        return t > deltaT ? t : Double.NaN;
    }
}

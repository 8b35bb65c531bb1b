package studio.engine.geometry;

import studio.engine.accel.TriangleLeaves;
import studio.engine.math.Fp;

/**
 * A mesh triangle's hit record, worked out once for the winning triangle of a search (pbrt's
 * Triangle::InteractionFromIntersection): the hit point as the barycentric combination of the
 * vertices with pbrt's error bound gamma(7)*sum|b_i*p_i|, so {@link Rays#spawn} offsets it like any
 * other hit, along the triangle's own (geometric) normal, which the hit carries beside the
 * interpolated one.
 */
final class TriangleHits {

    private static final double G7 = Fp.gamma(7);

    private TriangleHits() {
    }

    /**
     * Fills {@code hit} for triangle {@code tri} (vertex indices at {@code indices[3 tri ..]}) that
     * {@link TriangleLeaves#distance} accepted for the ray sheared as {@code f}: the same arithmetic,
     * so the same t; then the point, its error bound, the geometric normal and, with vertex normals
     * ({@code normals} non-null), the interpolated one turned to the geometric normal's side.
     */
    static void fill(double[] positions, double[] normals, int[] indices, int tri, RayShear f, Hit hit) {
        int kx = f.kx, ky = f.ky, kz = f.kz;
        double okx = f.okx, oky = f.oky, okz = f.okz, sx = f.sx, sy = f.sy, sz = f.sz;
        double[] p = positions;
        int ia = indices[3 * tri], ib = indices[3 * tri + 1], ic = indices[3 * tri + 2];
        int a = 3 * ia, b = 3 * ib, c = 3 * ic;
        double z0 = p[a + kz] - okz, z1 = p[b + kz] - okz, z2 = p[c + kz] - okz;
        double x0 = p[a + kx] - okx + sx * z0, y0 = p[a + ky] - oky + sy * z0;
        double x1 = p[b + kx] - okx + sx * z1, y1 = p[b + ky] - oky + sy * z1;
        double x2 = p[c + kx] - okx + sx * z2, y2 = p[c + ky] - oky + sy * z2;
        double e0 = x1 * y2 - y1 * x2, e1 = x2 * y0 - y2 * x0, e2 = x0 * y1 - y0 * x1;
        double invDet = 1 / (e0 + e1 + e2);
        double t = (e0 * (z0 * sz) + e1 * (z1 * sz) + e2 * (z2 * sz)) * invDet;
        double b0 = e0 * invDet, b1 = e1 * invDet, b2 = e2 * invDet;

        double px = b0 * p[a] + b1 * p[b] + b2 * p[c];
        double py = b0 * p[a + 1] + b1 * p[b + 1] + b2 * p[c + 1];
        double pz = b0 * p[a + 2] + b1 * p[b + 2] + b2 * p[c + 2];
        double ex = G7 * (Math.abs(b0 * p[a]) + Math.abs(b1 * p[b]) + Math.abs(b2 * p[c]));
        double ey = G7 * (Math.abs(b0 * p[a + 1]) + Math.abs(b1 * p[b + 1]) + Math.abs(b2 * p[c + 1]));
        double ez = G7 * (Math.abs(b0 * p[a + 2]) + Math.abs(b1 * p[b + 2]) + Math.abs(b2 * p[c + 2]));

        double ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
        double vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
        double gx = uy * vz - uz * vy, gy = uz * vx - ux * vz, gz = ux * vy - uy * vx;
        double gm = Math.max(Math.abs(gx), Math.max(Math.abs(gy), Math.abs(gz)));
        gx /= gm; gy /= gm; gz /= gm;
        double gl = Math.sqrt(gx * gx + gy * gy + gz * gz);
        gx /= gl;
        gy /= gl;
        gz /= gl;
        double nx = gx, ny = gy, nz = gz;
        if (normals != null) {
            double[] n = normals;
            double sxn = b0 * n[a] + b1 * n[b] + b2 * n[c];
            double syn = b0 * n[a + 1] + b1 * n[b + 1] + b2 * n[c + 1];
            double szn = b0 * n[a + 2] + b1 * n[b + 2] + b2 * n[c + 2];
            double sl = Math.sqrt(sxn * sxn + syn * syn + szn * szn);
            if (sl > 0 && Double.isFinite(sl)) {
                double flip = sxn * nx + syn * ny + szn * nz < 0 ? -1 / sl : 1 / sl;
                nx = sxn * flip;
                ny = syn * flip;
                nz = szn * flip;
            }
        }
        hit.set(t, px, py, pz, nx, ny, nz, gx, gy, gz, ex, ey, ez);
        hit.triangle = tri;
        hit.b1 = b1;
        hit.b2 = b2;
    }
}

package studio.engine.accel;

import studio.engine.geometry.Ray;

/**
 * Triangles as {@link Primitives}, with the Möller-Trumbore test in double: the same for the binary and
 * the wide walk, so comparing the two measures the trees, not the triangle test.
 */
public final class TrianglePrimitives implements Primitives {

    private final double[] positions;
    private final int[] indices;
    private final double[] boxes;

    /** Vertices as (x, y, z) triples and triangles as vertex index triples. */
    public TrianglePrimitives(double[] positions, int[] indices) {
        this.positions = positions;
        this.indices = indices;
        int n = indices.length / 3;
        boxes = new double[6 * n];
        for (int t = 0; t < n; t++) {
            for (int k = 0; k < 3; k++) {
                double a = positions[3 * indices[3 * t] + k], b = positions[3 * indices[3 * t + 1] + k],
                        c = positions[3 * indices[3 * t + 2] + k];
                boxes[6 * t + k] = Math.min(a, Math.min(b, c));
                boxes[6 * t + 3 + k] = Math.max(a, Math.max(b, c));
            }
        }
    }

    @Override
    public double distance(int p, Ray ray, double tMax) {
        int a = 3 * indices[3 * p], b = 3 * indices[3 * p + 1], c = 3 * indices[3 * p + 2];
        double[] v = positions;
        double e1x = v[b] - v[a], e1y = v[b + 1] - v[a + 1], e1z = v[b + 2] - v[a + 2];
        double e2x = v[c] - v[a], e2y = v[c + 1] - v[a + 1], e2z = v[c + 2] - v[a + 2];
        double px = ray.dy * e2z - ray.dz * e2y, py = ray.dz * e2x - ray.dx * e2z, pz = ray.dx * e2y - ray.dy * e2x;
        double det = e1x * px + e1y * py + e1z * pz;
        if (det == 0) {
            return Double.NaN;
        }
        double inv = 1 / det;
        double sx = ray.ox - v[a], sy = ray.oy - v[a + 1], sz = ray.oz - v[a + 2];
        double u = (sx * px + sy * py + sz * pz) * inv;
        if (u < 0 || u > 1) {
            return Double.NaN;
        }
        double qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
        double w = (ray.dx * qx + ray.dy * qy + ray.dz * qz) * inv;
        if (w < 0 || u + w > 1) {
            return Double.NaN;
        }
        double t = (e2x * qx + e2y * qy + e2z * qz) * inv;
        return t > 0 && t < tMax ? t : Double.NaN;
    }

    @Override
    public double[] boxes() {
        return boxes;
    }

    @Override
    public int count() {
        return indices.length / 3;
    }
}

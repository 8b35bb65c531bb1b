package studio.engine.geometry;

import java.util.Arrays;

import studio.engine.accel.Aabb;
import studio.engine.math.Rotation;
import studio.engine.math.Vec3;

/**
 * Placing a mesh's object-space data in the world, for {@link TriangleMesh}: vertices rotated,
 * scaled and moved, normals rotated, zero-area triangles dropped, and the tree's boxes fitted to
 * the placed vertices. Setup code, run once per mesh (or per move), never per ray.
 */
final class MeshPlacement {

    private MeshPlacement() {
    }

    /** The positions rotated and scaled, not yet moved. */
    static double[] unplacedPositions(double[] object, Rotation r, double scale) {
        double m00 = r.get(0, 0), m01 = r.get(0, 1), m02 = r.get(0, 2);
        double m10 = r.get(1, 0), m11 = r.get(1, 1), m12 = r.get(1, 2);
        double m20 = r.get(2, 0), m21 = r.get(2, 1), m22 = r.get(2, 2);
        double[] rotated = new double[object.length];
        Runs.over(object.length / 3, (from, to) -> {
            for (int i = 3 * from; i < 3 * to; i += 3) {
                double x = scale * object[i], y = scale * object[i + 1], z = scale * object[i + 2];
                rotated[i] = m00 * x + m01 * y + m02 * z;
                rotated[i + 1] = m10 * x + m11 * y + m12 * z;
                rotated[i + 2] = m20 * x + m21 * y + m22 * z;
            }
        });
        return rotated;
    }

    /** The unplaced positions moved to {@code position}. */
    static double[] moved(double[] unplaced, Vec3 position) {
        double tx = position.x(), ty = position.y(), tz = position.z();
        double[] world = new double[unplaced.length];
        Runs.over(unplaced.length / 3, (from, to) -> {
            for (int i = 3 * from; i < 3 * to; i += 3) {
                world[i] = tx + unplaced[i];
                world[i + 1] = ty + unplaced[i + 1];
                world[i + 2] = tz + unplaced[i + 2];
                if (!Double.isFinite(world[i]) || !Double.isFinite(world[i + 1]) || !Double.isFinite(world[i + 2])) {
                    throw new IllegalArgumentException("vertex " + i / 3 + " is not finite once placed in the world");
                }
            }
        });
        return world;
    }

    /**
     * The BVH's boxes for these positions: each leaf's the exact bounds of its triangles, each
     * interior node's the union of its children's (children come after their parent, so one pass
     * from the last node back).
     */
    static double[] fitted(double[] p, int[] indices, int[] links, int nodeCount) {
        double[] b = new double[6 * nodeCount];
        Runs.over(nodeCount, (from, to) -> {
            for (int node = nodeCount - 1 - from; node > nodeCount - 1 - to; node--) {
                int o = 3 * node, k = 6 * node;
                int count = links[o + 1];
                if (count >= 0) {
                    for (int axis = 0; axis < 3; axis++) {
                        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
                        for (int i = 3 * links[o], end = 3 * (links[o] + count); i < end; i++) {
                            double v = p[3 * indices[i] + axis];
                            lo = Math.min(lo, v);
                            hi = Math.max(hi, v);
                        }
                        b[k + axis] = lo;
                        b[k + 3 + axis] = hi;
                    }
                } else {
                    int left = 6 * (node + 1), right = 6 * links[o];
                    for (int axis = 0; axis < 3; axis++) {
                        b[k + axis] = Math.min(b[left + axis], b[right + axis]);
                        b[k + 3 + axis] = Math.max(b[left + 3 + axis], b[right + 3 + axis]);
                    }
                }
            }
        });
        return b;
    }

    static Aabb rootBounds(double[] b) {
        return new Aabb(b[0], b[1], b[2], b[3], b[4], b[5]);
    }

    static double[] worldNormals(double[] object, Rotation r) {
        double[] world = new double[object.length];
        Runs.over(object.length / 3, (from, to) -> {
            for (int i = 3 * from; i < 3 * to; i += 3) {
                Vec3 n = r.apply(new Vec3(object[i], object[i + 1], object[i + 2])).normalized();
                world[i] = n.x();
                world[i + 1] = n.y();
                world[i + 2] = n.z();
            }
        });
        return world;
    }

    /** The triangles whose cross product at these positions is non-zero, in their given order. */
    static int[] nonDegenerate(int[] indices, double[] p) {
        int[] kept = new int[indices.length];
        int[] n = {0};
        Runs.over(indices.length / 3, (from, to) -> {
            int k = n[0];
            for (int i = 3 * from; i < 3 * to; i += 3) {
                if (hasArea(indices, i, p)) {
                    kept[k++] = indices[i];
                    kept[k++] = indices[i + 1];
                    kept[k++] = indices[i + 2];
                }
            }
            n[0] = k;
        });
        return n[0] == kept.length ? kept : Arrays.copyOf(kept, n[0]);
    }

    /** Whether every triangle's cross product at these positions is non-zero. */
    static boolean haveArea(int[] indices, double[] p) {
        boolean[] all = {true};
        Runs.over(indices.length / 3, (from, to) -> {
            for (int i = 3 * from; i < 3 * to && all[0]; i += 3) {
                all[0] = hasArea(indices, i, p);
            }
        });
        return all[0];
    }

    static boolean hasArea(int[] indices, int i, double[] p) {
        int a = 3 * indices[i], b = 3 * indices[i + 1], c = 3 * indices[i + 2];
        double ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
        double vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
        double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
        return (cx != 0 || cy != 0 || cz != 0) && Double.isFinite(cx) && Double.isFinite(cy) && Double.isFinite(cz);
    }

    static void triangleBounds(double[] positions, int[] tris, int t, double[] out) {
        int a = 3 * tris[3 * t], b = 3 * tris[3 * t + 1], c = 3 * tris[3 * t + 2];
        for (int k = 0; k < 3; k++) {
            double pa = positions[a + k], pb = positions[b + k], pc = positions[c + k];
            out[6 * t + k] = Math.min(pa, Math.min(pb, pc));
            out[6 * t + 3 + k] = Math.max(pa, Math.max(pb, pc));
        }
    }
}

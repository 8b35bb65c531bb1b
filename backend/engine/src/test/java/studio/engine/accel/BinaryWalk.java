package studio.engine.accel;

import studio.engine.geometry.Ray;

/**
 * The closest-hit and any-hit walks of a binary {@link Bvh}, as the engine's traversals do them
 * (the double {@link Slab} test, nearer child first, a missed node never pushed; any-hit by escape
 * indices), over any {@link Primitives}: the reference a {@link WideWalk} must agree with, and the
 * baseline of the wide BVH benchmark. One per thread.
 */
public final class BinaryWalk {

    private final Bvh bvh;
    private final Primitives leaves;
    private final int[] stack = new int[Bvh.STACK_SIZE];
    private final double[] stackEntry = new double[Bvh.STACK_SIZE];
    /** The distance of the last {@link #closest} hit. */
    public double t;

    public BinaryWalk(Bvh bvh, Primitives leaves) {
        this.bvh = bvh;
        this.leaves = leaves;
    }

    /**
     * The primitive of the nearest hit with 0 &lt; t &lt; tMax, -1 if none; of hits at the same t
     * the lowest primitive index, so the answer does not depend on the order of the walk.
     */
    public int closest(Ray ray, double tMax) {
        double[] nb = bvh.bounds();
        int[] links = bvh.nodes();
        int[] prims = bvh.primitives();
        double ox = ray.ox, oy = ray.oy, oz = ray.oz, ix = 1 / ray.dx, iy = 1 / ray.dy, iz = 1 / ray.dz;
        boolean nanFree = Slab.nanFree(ox, oy, oz, ix, iy, iz);
        double best = tMax;
        int winner = -1, sp = 0, node = 0;
        double entry = Slab.entry(nb, 0, ox, oy, oz, ix, iy, iz, nanFree, best);
        while (true) {
            if (entry <= best) {
                int o = 3 * node, count = links[o + 1];
                if (count < 0) {
                    int left = node + 1, right = links[o];
                    double inLeft = Slab.entry(nb, 6 * left, ox, oy, oz, ix, iy, iz, nanFree, best);
                    double inRight = Slab.entry(nb, 6 * right, ox, oy, oz, ix, iy, iz, nanFree, best);
                    boolean hitLeft = inLeft <= best, hitRight = inRight <= best;
                    if (hitLeft && hitRight) {
                        boolean leftFirst = inLeft <= inRight;
                        stack[sp] = leftFirst ? right : left;
                        stackEntry[sp++] = leftFirst ? inRight : inLeft;
                        node = leftFirst ? left : right;
                        entry = leftFirst ? inLeft : inRight;
                        continue;
                    }
                    if (hitLeft || hitRight) {
                        node = hitLeft ? left : right;
                        entry = hitLeft ? inLeft : inRight;
                        continue;
                    }
                } else {
                    for (int slot = links[o], end = slot + count; slot < end; slot++) {
                        int p = prims[slot];
                        double d = leaves.distance(p, ray, winner < 0 ? tMax : Math.nextUp(best));
                        if (d < best || (d == best && p < winner)) {
                            best = d;
                            winner = p;
                        }
                    }
                }
            }
            if (sp == 0) {
                break;
            }
            node = stack[--sp];
            entry = stackEntry[sp];
        }
        t = best;
        return winner;
    }

    /** Whether some primitive is hit with 0 &lt; t &lt; tMax. */
    public boolean occluded(Ray ray, double tMax) {
        double[] nb = bvh.bounds();
        int[] links = bvh.nodes();
        int[] prims = bvh.primitives();
        double ox = ray.ox, oy = ray.oy, oz = ray.oz, ix = 1 / ray.dx, iy = 1 / ray.dy, iz = 1 / ray.dz;
        boolean nanFree = Slab.nanFree(ox, oy, oz, ix, iy, iz);
        int node = 0, end = bvh.nodeCount();
        while (node < end) {
            int o = 3 * node;
            if (Slab.hits(nb, 6 * node, ox, oy, oz, ix, iy, iz, nanFree, tMax)) {
                int count = links[o + 1];
                if (count < 0) {
                    node++;
                    continue;
                }
                for (int slot = links[o], last = slot + count; slot < last; slot++) {
                    if (!Double.isNaN(leaves.distance(prims[slot], ray, tMax))) {
                        return true;
                    }
                }
            }
            node = links[o + 2];
        }
        return false;
    }
}

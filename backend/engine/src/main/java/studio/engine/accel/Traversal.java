package studio.engine.accel;

import studio.engine.geometry.Frustum;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;

/**
 * The walk of a {@link Bvh}: the one closest-hit and the one any-hit traversal of the engine, for
 * the scene's shapes and for each mesh's triangles alike (their {@link Leaves}). Node boxes are
 * met through the robust {@link Slab} test.
 *
 * <p>Closest hit: both children's boxes are tested at their parent, the one the ray enters first
 * is visited, the other waits on a stack with its entry distance (skipped when popped if the cull
 * distance has fallen below it since), and a child the ray misses is never pushed. Any hit: no
 * order and no stack; a missed node, or a finished leaf, escapes to the node after its subtree.
 *
 * <p>This class is where a wider tree goes: a later change that walks nodes of four boxes tested
 * at once replaces the node loops of {@link #nearest} and {@link #any} here and keeps the
 * {@link Leaves} calls, so neither the scene nor a mesh changes.
 */
public final class Traversal {

    private final double[] nodeBounds;
    private final int[] links;
    private final int nodeCount;
    private final Leaves leaves;

    /**
     * Walks the tree given by {@code nodeBounds} (six doubles a node) and {@code links} (three ints
     * a node, see {@link Bvh}), whose leaf slots {@code leaves} tests. The arrays are kept, not copied.
     */
    public Traversal(double[] nodeBounds, int[] links, Leaves leaves) {
        this.nodeBounds = nodeBounds;
        this.links = links;
        this.nodeCount = links.length / 3;
        this.leaves = leaves;
    }

    /**
     * Visits every leaf the ray may hold a winner in, nearest first, and lets the leaves test it:
     * starts with cull distance {@code cull} (at most {@code tMax}) and returns the last one.
     * {@code stack} and {@code stackEntry} need {@link Bvh#STACK_SIZE} entries each and are
     * this walk's alone while it runs (a mesh inside the scene's walk uses a second pair).
     */
    public double nearest(Ray ray, double tMax, double cull, Hit hit, int[] stack, double[] stackEntry) {
        double ox = ray.ox, oy = ray.oy, oz = ray.oz;
        double ix = 1 / ray.dx, iy = 1 / ray.dy, iz = 1 / ray.dz;
        boolean nanFree = Slab.nanFree(ox, oy, oz, ix, iy, iz);
        double[] nb = nodeBounds;
        int[] links = this.links;
        Leaves leaves = this.leaves;
        int sp = 0, node = 0;
        double entry = Slab.entry(nb, 0, ox, oy, oz, ix, iy, iz, nanFree, cull);
        while (true) {
            if (entry <= cull) { // a miss is NaN: false
                int o = 3 * node;
                int count = links[o + 1];
                if (count < 0) {
                    int left = node + 1, right = links[o];
                    double inLeft = Slab.entry(nb, 6 * left, ox, oy, oz, ix, iy, iz, nanFree, cull);
                    double inRight = Slab.entry(nb, 6 * right, ox, oy, oz, ix, iy, iz, nanFree, cull);
                    boolean hitLeft = inLeft <= cull, hitRight = inRight <= cull;
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
                    int first = links[o];
                    cull = leaves.nearest(first, first + count, ray, tMax, cull, hit);
                }
            }
            if (sp == 0) {
                return cull;
            }
            node = stack[--sp];
            entry = stackEntry[sp];
        }
    }

    /** Whether some leaf primitive lies on the ray with 0 &lt; t &lt; tMax. */
    public boolean any(Ray ray, double tMax) {
        double ox = ray.ox, oy = ray.oy, oz = ray.oz;
        double ix = 1 / ray.dx, iy = 1 / ray.dy, iz = 1 / ray.dz;
        boolean nanFree = Slab.nanFree(ox, oy, oz, ix, iy, iz);
        double[] nb = nodeBounds;
        int[] links = this.links;
        Leaves leaves = this.leaves;
        int node = 0, end = nodeCount;
        while (node < end) {
            int o = 3 * node;
            if (Slab.hits(nb, 6 * node, ox, oy, oz, ix, iy, iz, nanFree, tMax)) {
                int count = links[o + 1];
                if (count < 0) {
                    node++;
                    continue;
                }
                int first = links[o];
                if (leaves.any(first, first + count, ray, tMax)) {
                    return true;
                }
            }
            node = links[o + 2];
        }
        return false;
    }

    /**
     * Into {@code out} from index {@code from} on: the leaf slots a ray inside the pyramid can
     * meet, those in leaves whose node boxes it may meet and whose own boxes ({@code slotBoxes},
     * six doubles a slot) it may meet too. Returns the index after the last, or -1 when they would
     * not fit. {@code stack} needs {@link Bvh#STACK_SIZE} ints.
     */
    public int slotsIn(Frustum pyramid, double[] slotBoxes, int[] out, int from, int[] stack) {
        double[] nb = nodeBounds;
        int[] links = this.links;
        int n = from, sp = 0, node = 0;
        while (true) {
            if (pyramid.mayMeet(nb, 6 * node)) {
                int o = 3 * node;
                int count = links[o + 1];
                if (count < 0) {
                    stack[sp++] = links[o];
                    node++;
                    continue;
                }
                for (int slot = links[o], end = slot + count; slot < end; slot++) {
                    if (count == 1 || pyramid.mayMeet(slotBoxes, 6 * slot)) {
                        if (n == out.length) {
                            return -1;
                        }
                        out[n++] = slot;
                    }
                }
            }
            if (sp == 0) {
                return n;
            }
            node = stack[--sp];
        }
    }
}

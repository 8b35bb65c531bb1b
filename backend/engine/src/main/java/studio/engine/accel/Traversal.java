package studio.engine.accel;

import studio.engine.geometry.Frustum;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.memory.MemoryGate;

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
 * <p>Where the Vector API box test is on ({@link WideBoxTests#vectorized}: JDK 20 or newer with
 * {@code --add-modules jdk.incubator.vector} and the optimising compiler) both walks go through a
 * {@link WideBvh} collapsed from the binary tree instead, eight boxes tested at once, and the same
 * {@link Leaves} calls, faster in the kernel benchmark ({@code studio-bench.jar kernel}); a scalar
 * wide walk was no faster than this binary one ({@code studio-bench.jar wide}), so a scalar JVM
 * keeps the binary walk (docs/speed.md). The float box test keeps every
 * node the double one keeps ({@link WideRay}), and the leaves decide ties by declaration order, not
 * by the order they are met, so both walks find the same hits and renders stay bit-identical.
 * A tree of fewer than {@link #WIDE_MIN_SLOTS} leaf slots, and {@link #slotsIn} always, walk the binary tree.
 */
public final class Traversal {

    /** Whether traversals of this JVM walk wide trees. */
    static final boolean WIDE = WideBoxTests.vectorized();
    private static final WideBoxTest BOXES = WideBoxTests.get();
    /**
     * Leaf slots a tree needs for its walk to go wide: in a tree of a few objects setting up the
     * float ray costs more than the few double box tests it spares (the still life in
     * {@code backend/bench/embree/compare.sh} on JDK 25).
     */
    static final int WIDE_MIN_SLOTS = 16;

    private final double[] nodeBounds;
    private final int[] links;
    private final int nodeCount;
    private final Leaves leaves;
    /** The wide tree, or null when this JVM walks the binary one. */
    private final WideBvh wide;

    /**
     * Walks the tree given by {@code nodeBounds} (six doubles a node) and {@code links} (three ints
     * a node, see {@link Bvh}), whose leaf slots {@code leaves} tests. The arrays are kept, not copied.
     */
    public Traversal(double[] nodeBounds, int[] links, Leaves leaves) {
        this(nodeBounds, links, leaves, MemoryGate.UNLIMITED);
    }

    /** As above, asking {@code memory} before the wide tree's arrays where one is built. */
    public Traversal(double[] nodeBounds, int[] links, Leaves leaves, MemoryGate memory) {
        this(nodeBounds, links, leaves, memory, WIDE && slots(links) >= WIDE_MIN_SLOTS);
    }

    /**
     * As above, walking the wide tree (with this JVM's box test) if {@code wide}, else the binary
     * one, whatever this JVM would choose: the same hits either way, which the tests hold the two
     * walks to, and the wide BVH benchmark times.
     */
    Traversal(double[] nodeBounds, int[] links, Leaves leaves, MemoryGate memory, boolean wide) {
        this.nodeBounds = nodeBounds;
        this.links = links;
        this.nodeCount = links.length / 3;
        this.leaves = leaves;
        this.wide = wide ? WideBvh.of(nodeBounds, links, memory) : null;
    }

    /** The leaf slots of the tree with these links: the sum of its leaves' counts. */
    private static int slots(int[] links) {
        int slots = 0;
        for (int o = 1; o < links.length; o += 3) {
            slots += Math.max(links[o], 0);
        }
        return slots;
    }

    /**
     * Visits every leaf the ray may hold a winner in, nearest first, and lets the leaves test it:
     * starts with cull distance {@code cull} (at most {@code tMax}) and returns the last one.
     * {@code stack} and {@code stackEntry} need {@link Bvh#STACK_SIZE} entries each and are
     * this walk's alone while it runs (a mesh inside the scene's walk uses a second pair), and so is
     * {@code scratch}, which the wide walk uses instead (null where {@link WideScratch#ifUsed} is).
     */
    public double nearest(Ray ray, double tMax, double cull, Hit hit, int[] stack, double[] stackEntry,
                          WideScratch scratch) {
        if (wide != null) {
            return nearestWide(ray, tMax, cull, hit, scratch);
        }
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

    /**
     * Whether some leaf primitive lies on the ray with 0 &lt; t &lt; tMax. {@code scratch} is this
     * walk's alone while it runs, as {@link #nearest}'s.
     */
    public boolean any(Ray ray, double tMax, WideScratch scratch) {
        if (wide != null) {
            return anyWide(ray, tMax, scratch);
        }
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
     * {@link #nearest} over the wide tree: each node's eight boxes at once; the interior children met
     * wait on the stack by entry distance, nearest on top, and one popped is skipped when the cull
     * distance has fallen below its entry since; a leaf met is tested at once.
     */
    private double nearestWide(Ray ray, double tMax, double cull, Hit hit, WideScratch s) {
        float[] boxes = wide.boxes();
        int[] children = wide.children();
        Leaves leaves = this.leaves;
        WideRay r = s.ray.set(ray.ox, ray.oy, ray.oz, ray.dx, ray.dy, ray.dz);
        float[] entry = s.entry;
        int[] stack = s.stack;
        float[] stackEntry = s.stackEntry;
        float limit = WideRay.limit(cull);
        int sp = 0, node = 0;
        while (true) {
            int mask = BOXES.test(boxes, WideBvh.FLOATS * node, r, limit, entry);
            int first = sp;
            while (mask != 0) {
                int k = Integer.numberOfTrailingZeros(mask);
                mask &= mask - 1;
                int link = children[WideBvh.WIDTH * node + k];
                if (link >= 0) {
                    // insert by entry distance, farthest deepest, so the nearest is popped first
                    float e = entry[k];
                    int i = sp++;
                    while (i > first && stackEntry[i - 1] < e) {
                        stack[i] = stack[i - 1];
                        stackEntry[i] = stackEntry[i - 1];
                        i--;
                    }
                    stack[i] = link;
                    stackEntry[i] = e;
                } else if (link != WideBvh.EMPTY) {
                    int slot = WideBvh.leafFirst(link);
                    double found = leaves.nearest(slot, slot + WideBvh.leafCount(link), ray, tMax, cull, hit);
                    if (found != cull) {
                        cull = found;
                        limit = WideRay.limit(cull);
                    }
                }
            }
            do {
                if (sp == 0) {
                    return cull;
                }
                node = stack[--sp];
            } while (stackEntry[sp] > limit);
        }
    }

    /** {@link #any} over the wide tree: the children met are pushed in any order; the first hit ends it. */
    private boolean anyWide(Ray ray, double tMax, WideScratch s) {
        float[] boxes = wide.boxes();
        int[] children = wide.children();
        Leaves leaves = this.leaves;
        WideRay r = s.ray.set(ray.ox, ray.oy, ray.oz, ray.dx, ray.dy, ray.dz);
        float[] entry = s.entry;
        int[] stack = s.stack;
        float limit = WideRay.limit(tMax);
        int sp = 0, node = 0;
        while (true) {
            int mask = BOXES.test(boxes, WideBvh.FLOATS * node, r, limit, entry);
            while (mask != 0) {
                int k = Integer.numberOfTrailingZeros(mask);
                mask &= mask - 1;
                int link = children[WideBvh.WIDTH * node + k];
                if (link >= 0) {
                    stack[sp++] = link;
                } else if (link != WideBvh.EMPTY) {
                    int slot = WideBvh.leafFirst(link);
                    if (leaves.any(slot, slot + WideBvh.leafCount(link), ray, tMax)) {
                        return true;
                    }
                }
            }
            if (sp == 0) {
                return false;
            }
            node = stack[--sp];
        }
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

    /**
     * Whether the pyramid, inside the box {@code reach} ({@link Frustum#bounds}), may meet the box
     * of a slot other than {@code except} (-1: none): the walk of {@link #slotsIn}, a node first
     * tested against {@code reach}, stopping at the first such slot.
     */
    public boolean anyIn(Frustum pyramid, double[] reach, double[] slotBoxes, int except, int[] stack) {
        double[] nb = nodeBounds;
        int[] links = this.links;
        int sp = 0, node = 0;
        double x0 = reach[0], y0 = reach[1], z0 = reach[2], x1 = reach[3], y1 = reach[4], z1 = reach[5];
        while (true) {
            int b = 6 * node;
            if (nb[b] <= x1 && nb[b + 1] <= y1 && nb[b + 2] <= z1 && nb[b + 3] >= x0 && nb[b + 4] >= y0
                    && nb[b + 5] >= z0 && pyramid.mayMeet(nb, b)) {
                int o = 3 * node;
                int count = links[o + 1];
                if (count < 0) {
                    stack[sp++] = links[o];
                    node++;
                    continue;
                }
                for (int slot = links[o], end = slot + count; slot < end; slot++) {
                    if (slot != except && (count == 1 || pyramid.mayMeet(slotBoxes, 6 * slot))) {
                        return true;
                    }
                }
            }
            if (sp == 0) {
                return false;
            }
            node = stack[--sp];
        }
    }
}

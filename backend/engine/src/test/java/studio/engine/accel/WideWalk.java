package studio.engine.accel;

import studio.engine.geometry.Ray;

/**
 * The closest-hit and any-hit walks of a {@link WideBvh}, over any {@link Primitives}: how the
 * engine's one traversal in this package uses the wide tree (see the report of issue 47's wide BVH
 * part). Each node's eight boxes are tested at once by a {@link WideBoxTest}; a leaf met is tested
 * at once; the interior children met wait on a stack with their entry distances, the nearest on
 * top, and one popped is skipped if a hit nearer than its entry has been found since. One per
 * thread; allocates nothing.
 */
public final class WideWalk {

    private final WideBvh tree;
    private final Primitives leaves;
    private final WideBoxTest boxTest;
    private final WideRay wide = new WideRay();
    private final float[] entry = new float[WideBvh.WIDTH];
    private final int[] stack = new int[WideBvh.STACK_SIZE];
    private final float[] stackEntry = new float[WideBvh.STACK_SIZE];
    /** The distance of the last {@link #closest} hit. */
    public double t;

    /** A walk with this JVM's box test ({@link WideBoxTests#get}). */
    public WideWalk(WideBvh tree, Primitives leaves) {
        this(tree, leaves, WideBoxTests.get());
    }

    public WideWalk(WideBvh tree, Primitives leaves, WideBoxTest boxTest) {
        this.tree = tree;
        this.leaves = leaves;
        this.boxTest = boxTest;
    }

    /** As {@link BinaryWalk#closest}: the same primitive and distance. */
    public int closest(Ray ray, double tMax) {
        float[] boxes = tree.boxes();
        int[] children = tree.children();
        int[] prims = tree.primitives();
        WideRay r = wide.set(ray.ox, ray.oy, ray.oz, ray.dx, ray.dy, ray.dz);
        double best = tMax;
        float limit = WideRay.limit(best);
        int winner = -1, sp = 0, node = 0;
        while (true) {
            int mask = boxTest.test(boxes, WideBvh.FLOATS * node, r, limit, entry);
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
                    for (int slot = WideBvh.leafFirst(link), end = slot + WideBvh.leafCount(link); slot < end; slot++) {
                        int p = prims[slot];
                        double d = leaves.distance(p, ray, winner < 0 ? tMax : Math.nextUp(best));
                        if (d < best || (d == best && p < winner)) {
                            best = d;
                            winner = p;
                            limit = WideRay.limit(best);
                        }
                    }
                }
            }
            do {
                if (sp == 0) {
                    t = best;
                    return winner;
                }
                node = stack[--sp];
            } while (stackEntry[sp] > limit);
        }
    }

    /** As {@link BinaryWalk#occluded}. */
    public boolean occluded(Ray ray, double tMax) {
        float[] boxes = tree.boxes();
        int[] children = tree.children();
        int[] prims = tree.primitives();
        WideRay r = wide.set(ray.ox, ray.oy, ray.oz, ray.dx, ray.dy, ray.dz);
        float limit = WideRay.limit(tMax);
        int sp = 0, node = 0;
        while (true) {
            int mask = boxTest.test(boxes, WideBvh.FLOATS * node, r, limit, entry);
            while (mask != 0) {
                int k = Integer.numberOfTrailingZeros(mask);
                mask &= mask - 1;
                int link = children[WideBvh.WIDTH * node + k];
                if (link >= 0) {
                    stack[sp++] = link;
                } else if (link != WideBvh.EMPTY) {
                    for (int slot = WideBvh.leafFirst(link), end = slot + WideBvh.leafCount(link); slot < end; slot++) {
                        if (!Double.isNaN(leaves.distance(prims[slot], ray, tMax))) {
                            return true;
                        }
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

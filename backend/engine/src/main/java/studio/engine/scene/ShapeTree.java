package studio.engine.scene;

import java.util.Arrays;

import studio.engine.accel.Aabb;
import studio.engine.accel.Bvh;
import studio.engine.geometry.Shape;

/**
 * A {@link ShapeSet}'s tree over its bounded shapes: the slot each shape sits at, the slots' boxes,
 * the node boxes and links ({@link Bvh}), and the set's unbounded shapes (planes) beside it.
 * Built with the SAH, or <em>refitted</em> from the tree of a set that held the same shapes but a
 * few ({@link #refit}): the same nodes and slots, each node's box the union of its slots' new boxes,
 * worked out bottom-up. A live view's drag moves one object of 10,000 a revision; the scene of 10,001
 * objects is then assembled in about 1.5 ms of CPU time instead of 11-13 with its tree built
 * ({@code PatchRevisionBench} in the server's tests). A
 * refitted tree finds the same hits as a built one: which shape wins is the leaves' tie rule, not
 * the tree's; only its speed can suffer, so a refit whose SAH cost grows past
 * {@value #REBUILD_COST} times the built tree's is refused and the tree built again.
 */
final class ShapeTree {

    /**
     * A refitted tree may cost this many times what the tree it was built as cost (SAH, relative to
     * its root's area). Reasoned, not tuned on a benchmark: a quarter more box tests a ray is about
     * what a build's 11-13 ms for 10,000 objects are worth over a few one-sample frames; dragging one
     * object about within the scene stays below it ({@code SceneReusingTest}).
     */
    static final double REBUILD_COST = 1.25;
    /** Cost of visiting a node relative to testing a shape, as the builder weighs it. */
    private static final double TRAVERSAL_COST = 1;

    /** Every shape of the set's scene, by declaration index (the members among them are in the tree or beside it). */
    final Shape[] shapes;
    /** Per slot, its shape's declaration index. */
    final int[] slotShapes;
    /** Per shape, its slot, or -1: unbounded, or not a member. */
    final int[] slotOfShape;
    /** Per slot, its shape's box (six doubles). */
    final double[] slotBoxes;
    /** The unbounded members, by declaration index. */
    final int[] planeIndex;
    final double[] nodeBounds;
    final int[] nodeLinks;
    /** The SAH cost of the tree as it was built (refits keep it, to compare with theirs). */
    final double builtCost;
    /** The slots whose shapes changed in the refit that made this tree (none for a built one). */
    final int[] changedSlots;

    private ShapeTree(Shape[] shapes, int[] slotShapes, int[] slotOfShape, double[] slotBoxes, int[] planeIndex,
                      double[] nodeBounds, int[] nodeLinks, double builtCost, int[] changedSlots) {
        this.shapes = shapes;
        this.slotShapes = slotShapes;
        this.slotOfShape = slotOfShape;
        this.slotBoxes = slotBoxes;
        this.planeIndex = planeIndex;
        this.nodeBounds = nodeBounds;
        this.nodeLinks = nodeLinks;
        this.builtCost = builtCost;
        this.changedSlots = changedSlots;
    }

    /** The tree over the members ({@code members[i]}; all if null) of {@code shapes} that are bounded (at least one). */
    static ShapeTree build(Shape[] shapes, boolean[] members) {
        int boundedCount = 0, memberCount = 0;
        for (int i = 0; i < shapes.length; i++) {
            if (members == null || members[i]) {
                memberCount++;
                boundedCount += shapes[i].bounds().isBounded() ? 1 : 0;
            }
        }
        int[] boundedIndex = new int[boundedCount];
        int[] planeIndex = new int[memberCount - boundedCount];
        double[] boxes = new double[6 * boundedCount];
        int b = 0, u = 0;
        for (int i = 0; i < shapes.length; i++) {
            if (members != null && !members[i]) {
                continue;
            }
            Aabb box = shapes[i].bounds();
            if (box.isBounded()) {
                box.copyTo(boxes, 6 * b);
                boundedIndex[b++] = i;
            } else {
                planeIndex[u++] = i;
            }
        }
        Bvh bvh = Bvh.build(boxes, boundedCount);
        int[] order = bvh.primitives();
        int[] slotShapes = new int[boundedCount];
        double[] slotBoxes = new double[6 * boundedCount];
        int[] slotOfShape = new int[shapes.length];
        Arrays.fill(slotOfShape, -1);
        for (int slot = 0; slot < boundedCount; slot++) {
            slotShapes[slot] = boundedIndex[order[slot]];
            slotOfShape[slotShapes[slot]] = slot;
            System.arraycopy(boxes, 6 * order[slot], slotBoxes, 6 * slot, 6);
        }
        return new ShapeTree(shapes, slotShapes, slotOfShape, slotBoxes, planeIndex, bvh.bounds(), bvh.nodes(),
                cost(bvh.bounds(), bvh.nodes()), new int[0]);
    }

    /**
     * This tree for {@code next}, the shapes of a scene of as many shapes of which those that are not
     * the very objects of this tree's (by identity) changed: refitted, sharing the links, slots and
     * planes. Null where it must be built: a changed shape went from bounded to unbounded or back,
     * or the refitted tree would cost more than {@value #REBUILD_COST} times the built one.
     */
    ShapeTree refit(Shape[] next, boolean[] members) {
        if (next.length != shapes.length) {
            return null;
        }
        int[] changed = new int[8];
        int count = 0;
        for (int i = 0; i < next.length; i++) {
            if (next[i] == shapes[i] || members != null && !members[i]) {
                continue;
            }
            boolean bounded = next[i].bounds().isBounded();
            if (bounded != (slotOfShape[i] >= 0)) {
                return null; // a plane became bounded or the other way round (a member either way: same membership)
            }
            if (bounded) {
                if (count == changed.length) {
                    changed = Arrays.copyOf(changed, 2 * count);
                }
                changed[count++] = slotOfShape[i];
            }
        }
        if (count == 0) {
            return new ShapeTree(next, slotShapes, slotOfShape, slotBoxes, planeIndex, nodeBounds, nodeLinks, builtCost,
                    new int[0]);
        }
        double[] boxes = slotBoxes.clone();
        for (int k = 0; k < count; k++) {
            next[slotShapes[changed[k]]].bounds().copyTo(boxes, 6 * changed[k]);
        }
        double[] bounds = refitted(nodeLinks, boxes, nodeBounds.length);
        if (cost(bounds, nodeLinks) > REBUILD_COST * builtCost) {
            return null;
        }
        return new ShapeTree(next, slotShapes, slotOfShape, boxes, planeIndex, bounds, nodeLinks, builtCost,
                Arrays.copyOf(changed, count));
    }

    /** Node boxes for these links over these slot boxes: each leaf the union of its slots', each interior node of its children's. */
    static double[] refitted(int[] links, double[] slotBoxes, int length) {
        double[] b = new double[length];
        for (int node = links.length / 3 - 1; node >= 0; node--) {
            int o = 6 * node, count = links[3 * node + 1];
            if (count > 0) {
                int first = links[3 * node];
                System.arraycopy(slotBoxes, 6 * first, b, o, 6);
                for (int s = first + 1; s < first + count; s++) {
                    union(b, o, slotBoxes, 6 * s);
                }
            } else {
                // children come after their parent in depth-first order: both are refitted already
                System.arraycopy(b, o + 6, b, o, 6);
                union(b, o, b, 6 * links[3 * node]);
            }
        }
        return b;
    }

    private static void union(double[] into, int o, double[] box, int p) {
        for (int k = 0; k < 3; k++) {
            into[o + k] = Math.min(into[o + k], box[p + k]);
            into[o + 3 + k] = Math.max(into[o + 3 + k], box[p + 3 + k]);
        }
    }

    /**
     * The tree's SAH cost relative to its root's area: {@link #TRAVERSAL_COST} for each interior
     * node and one for each shape of a leaf, weighted by its box's area (pbrt's and the builder's
     * measure of how many tests a random ray makes).
     */
    static double cost(double[] bounds, int[] links) {
        double root = halfArea(bounds, 0);
        if (!(root > 0)) {
            return 0;
        }
        double sum = 0;
        for (int node = 0, n = links.length / 3; node < n; node++) {
            int count = links[3 * node + 1];
            sum += (count > 0 ? count : TRAVERSAL_COST) * halfArea(bounds, 6 * node);
        }
        return sum / root;
    }

    private static double halfArea(double[] b, int o) {
        double dx = b[o + 3] - b[o], dy = b[o + 4] - b[o + 1], dz = b[o + 5] - b[o + 2];
        return dx * dy + dy * dz + dz * dx;
    }

    /** The largest magnitude of the root box's coordinates. */
    double largest() {
        double largest = 0;
        for (int k = 0; k < 6; k++) {
            largest = Math.max(largest, Math.abs(nodeBounds[k]));
        }
        return largest;
    }

    Aabb rootBounds() {
        return new Aabb(nodeBounds[0], nodeBounds[1], nodeBounds[2], nodeBounds[3], nodeBounds[4], nodeBounds[5]);
    }
}

package studio.engine.accel;

import java.util.Arrays;

import studio.engine.memory.MemoryGate;

/**
 * Collapses a binary {@link Bvh} into a {@link WideBvh} top-down (pbrt-v4's and Embree's collapse):
 * a wide node starts from a binary node's two children and, while it has fewer than eight, replaces
 * the interior child of largest surface area by its two children; its leaves stay the binary
 * leaves, slot for slot. Each wide node thus stands for one to three binary levels, and the tree
 * has at most as many levels as the binary one.
 */
final class WideBvhCollapse {

    /** Leaf slots a wide link can name: 28 bits of first slot beside 3 of count. */
    private static final int MAX_SLOTS = 1 << 28;

    private final double[] bounds;
    private final int[] links;
    private final int binaryNodes;
    private final int[] primitives;
    private float[] boxes;
    private int[] children;
    private int count;
    private int depth;

    WideBvhCollapse(Bvh bvh, MemoryGate memory) {
        this(bvh.bounds(), bvh.nodes(), bvh.primitives(), memory);
    }

    /** The binary tree as its node bounds and links ({@link Bvh}); {@code primitives} may be null (then so is the wide tree's). */
    WideBvhCollapse(double[] bounds, int[] links, int[] primitives, MemoryGate memory) {
        this.bounds = bounds;
        this.links = links;
        this.binaryNodes = links.length / 3;
        this.primitives = primitives;
        if (primitives != null && primitives.length >= MAX_SLOTS) {
            throw new IllegalArgumentException("a wide BVH holds fewer than 2^28 primitives; got " + primitives.length);
        }
        // a binary tree of n nodes has (n - 1) / 2 interior nodes, and each wide node takes at least
        // one; the arrays are then copied to their final length (counted twice)
        int capacity = Math.max(1, (binaryNodes - 1) / 2);
        memory.reserve(2 * (MemoryGate.floats((long) WideBvh.FLOATS * capacity)
                + MemoryGate.ints((long) WideBvh.WIDTH * capacity)));
        boxes = new float[WideBvh.FLOATS * capacity];
        children = new int[WideBvh.WIDTH * capacity];
    }

    WideBvh collapse() {
        build(0, 1);
        return new WideBvh(Arrays.copyOf(boxes, WideBvh.FLOATS * count), Arrays.copyOf(children, WideBvh.WIDTH * count),
                primitives, depth);
    }

    /** Builds the wide node for binary node {@code node} and its subtree; returns its index. */
    private int build(int node, int level) {
        depth = Math.max(depth, level);
        int index = count++;
        int[] lanes = new int[WideBvh.WIDTH];
        int n;
        if (isLeafNode(node)) {
            lanes[0] = node; // a tree of one leaf: the root holds it as its one child
            n = 1;
        } else {
            lanes[0] = node + 1;
            lanes[1] = links[3 * node];
            n = 2;
            while (n < WideBvh.WIDTH) {
                int widest = -1;
                double widestArea = -1;
                for (int k = 0; k < n; k++) {
                    if (!isLeafNode(lanes[k]) && area(lanes[k]) > widestArea) {
                        widest = k;
                        widestArea = area(lanes[k]);
                    }
                }
                if (widest < 0) {
                    break;
                }
                int open = lanes[widest];
                lanes[widest] = open + 1;
                lanes[n++] = links[3 * open];
            }
        }
        int base = WideBvh.FLOATS * index;
        for (int k = 0; k < WideBvh.WIDTH; k++) {
            if (k < n) {
                int o = 6 * lanes[k];
                boxes[base + WideBvh.MIN_X + k] = WideBvh.floatBelow(bounds[o]);
                boxes[base + WideBvh.MIN_Y + k] = WideBvh.floatBelow(bounds[o + 1]);
                boxes[base + WideBvh.MIN_Z + k] = WideBvh.floatBelow(bounds[o + 2]);
                boxes[base + WideBvh.MAX_X + k] = WideBvh.floatAbove(bounds[o + 3]);
                boxes[base + WideBvh.MAX_Y + k] = WideBvh.floatAbove(bounds[o + 4]);
                boxes[base + WideBvh.MAX_Z + k] = WideBvh.floatAbove(bounds[o + 5]);
            } else {
                for (int a = 0; a < 3; a++) {
                    boxes[base + WideBvh.MIN_X + WideBvh.WIDTH * a + k] = Float.POSITIVE_INFINITY;
                    boxes[base + WideBvh.MAX_X + WideBvh.WIDTH * a + k] = Float.NEGATIVE_INFINITY;
                }
                children[WideBvh.WIDTH * index + k] = WideBvh.EMPTY;
            }
        }
        for (int k = 0; k < n; k++) {
            int child = lanes[k];
            children[WideBvh.WIDTH * index + k] = isLeafNode(child)
                    ? leaf(links[3 * child], links[3 * child + 1]) : build(child, level + 1);
        }
        return index;
    }

    private boolean isLeafNode(int node) {
        return links[3 * node + 1] > 0;
    }

    /** Half the surface area of binary node {@code node}'s box. */
    private double area(int node) {
        int o = 6 * node;
        double x = bounds[o + 3] - bounds[o], y = bounds[o + 4] - bounds[o + 1], z = bounds[o + 5] - bounds[o + 2];
        return x * y + y * z + z * x;
    }

    private static int leaf(int first, int count) {
        if (first + count > MAX_SLOTS) {
            throw new IllegalArgumentException("a wide BVH holds fewer than 2^28 primitives; got " + (first + count));
        }
        return WideBvh.leaf(first, count);
    }
}

package studio.engine.accel;

import studio.engine.memory.MemoryGate;

/**
 * A bounding volume hierarchy over primitives given only by their boxes, flattened into arrays in
 * depth-first order (pbrt's LinearBVHNode; sunflow's flat BIH). Node {@code i} has its box at
 * {@code bounds[6i .. 6i+5]} (minX, minY, minZ, maxX, maxY, maxZ; exact unions of the primitives'
 * boxes, so nothing is rounded) and three ints at {@code nodes[3i .. 3i+2]}:
 * <ul>
 *   <li>leaf: first slot, primitive count (1..{@value #LEAF_MAX}), escape;</li>
 *   <li>interior: right child, {@code ~axis} (negative: the split axis), escape. The left child is
 *       node {@code i + 1}.</li>
 * </ul>
 * The escape index is the first node after the subtree, which lets an any-hit traversal run
 * without a stack. A leaf's primitives are {@code primitives()[first .. first+count-1]}.
 *
 * <p>The tree is walked by {@link Traversal}, the engine's one closest-hit and one any-hit walk,
 * over the scene's shapes and each mesh's triangles alike ({@link Leaves}). A closest-hit walk
 * needs a stack of {@value #STACK_SIZE} ints and doubles: the builder keeps every tree at most
 * {@value #STACK_SIZE} levels deep.
 */
public final class Bvh {

    /** Most primitives in one leaf. */
    public static final int LEAF_MAX = 4;
    /** Ints a closest-hit traversal stack needs. */
    public static final int STACK_SIZE = 64;

    private final double[] bounds;
    private final int[] nodes;
    private final int[] primitives;
    private final int depth;
    private final long buildNanos;

    Bvh(double[] bounds, int[] nodes, int[] primitives, int depth, long buildNanos) {
        this.bounds = bounds;
        this.nodes = nodes;
        this.primitives = primitives;
        this.depth = depth;
        this.buildNanos = buildNanos;
    }

    /**
     * Builds a tree with binned SAH over {@code count} primitives whose boxes are
     * {@code primitiveBounds[6p .. 6p+5]} (minX, minY, minZ, maxX, maxY, maxZ, all finite). The
     * array is read, not kept or changed.
     */
    public static Bvh build(double[] primitiveBounds, int count) {
        return build(primitiveBounds, count, MemoryGate.UNLIMITED);
    }

    /** As above, asking {@code memory} before each array the build allocates or grows. */
    public static Bvh build(double[] primitiveBounds, int count, MemoryGate memory) {
        return new BvhBuilder(primitiveBounds, count, memory).build();
    }

    /** Node boxes, six doubles per node; read-only. */
    public double[] bounds() {
        return bounds;
    }

    /** Node links, three ints per node (see the class comment); read-only. */
    public int[] nodes() {
        return nodes;
    }

    /** Primitive indices in leaf order; read-only. */
    public int[] primitives() {
        return primitives;
    }

    public int nodeCount() {
        return nodes.length / 3;
    }

    /** Levels from the root to the deepest leaf, the root counting as one. */
    public int depth() {
        return depth;
    }

    /** Wall-clock time the build took. */
    public long buildNanos() {
        return buildNanos;
    }

    /** The root's box: the bounds of every primitive. */
    public Aabb rootBounds() {
        return new Aabb(bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5]);
    }
}

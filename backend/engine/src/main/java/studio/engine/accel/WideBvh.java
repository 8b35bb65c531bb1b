package studio.engine.accel;

import studio.engine.memory.MemoryGate;

/**
 * An eight-wide bounding volume hierarchy collapsed from a binary {@link Bvh} (Embree's BVH8): each
 * node holds the boxes of up to eight children, in float and structure-of-arrays form, so that one
 * {@link WideBoxTest} tests all eight with one ray in a few 256-bit vector instructions. Eight
 * rather than four: less CPU time in the kernel benchmark ({@code studio-bench.jar kernel}, JDK 25).
 *
 * <p>Node {@code i} keeps its children's boxes at {@code boxes()[48i .. 48i+47]}: minX of the eight
 * lanes, then minY, minZ, maxX, maxY, maxZ (eight floats each; offsets {@link #MIN_X} ..
 * {@link #MAX_Z}). Each box is the binary node's exact double box rounded outward to float
 * ({@link #floatBelow}, {@link #floatAbove}), so a float box test that is itself conservative
 * ({@link WideRay}) never drops a node the binary tree's double test keeps. Its links are
 * {@code children()[8i .. 8i+7]}, one per lane:
 * <ul>
 *   <li>{@code >= 0}: an interior child, the index of its wide node;</li>
 *   <li>{@link #EMPTY}: no child (its box is empty, +inf to -inf, and no ray meets it);</li>
 *   <li>otherwise a leaf: {@link #leafFirst} and {@link #leafCount} give its slots, the same slots
 *       of {@link Bvh#primitives()} the binary leaf had, so the primitive tests stay the exact
 *       double-precision ones and a traversal finds the same hits.</li>
 * </ul>
 * Node 0 is the root. A closest-hit traversal needs a stack of {@link #STACK_SIZE} entries: each
 * wide level pushes at most seven children, and the tree is no deeper than the binary one.
 */
public final class WideBvh {

    /** Children per node. */
    public static final int WIDTH = 8;
    /** Floats per node: six bounds for each of the lanes. */
    public static final int FLOATS = 6 * WIDTH;
    /** Offsets of a node's six bound arrays within its {@link #FLOATS} floats. */
    public static final int MIN_X = 0, MIN_Y = WIDTH, MIN_Z = 2 * WIDTH, MAX_X = 3 * WIDTH, MAX_Y = 4 * WIDTH,
            MAX_Z = 5 * WIDTH;
    /** The mask of a node test that keeps every lane. */
    public static final int ALL_LANES = (1 << WIDTH) - 1;
    /** The link of an empty lane. */
    public static final int EMPTY = -1;
    /** Entries a closest-hit traversal stack needs. */
    public static final int STACK_SIZE = (WIDTH - 1) * Bvh.STACK_SIZE + 1;

    private final float[] boxes;
    private final int[] children;
    private final int[] primitives;
    private final int depth;

    WideBvh(float[] boxes, int[] children, int[] primitives, int depth) {
        this.boxes = boxes;
        this.children = children;
        this.primitives = primitives;
        this.depth = depth;
    }

    /** Collapses {@code bvh} into eight-wide nodes (see {@link WideBvhCollapse}). */
    public static WideBvh of(Bvh bvh) {
        return of(bvh, MemoryGate.UNLIMITED);
    }

    /** As above, asking {@code memory} before the arrays it allocates. */
    public static WideBvh of(Bvh bvh, MemoryGate memory) {
        return new WideBvhCollapse(bvh, memory).collapse();
    }

    /**
     * Collapses the binary tree given by its node bounds and links (as {@link Bvh#bounds()} and
     * {@link Bvh#nodes()}, e.g. a moved mesh's refitted boxes); the wide tree's
     * {@link #primitives()} is null, its leaves naming slots only.
     */
    static WideBvh of(double[] nodeBounds, int[] links, MemoryGate memory) {
        return new WideBvhCollapse(nodeBounds, links, null, memory).collapse();
    }

    /** Child boxes, {@link #FLOATS} floats per node; read-only. */
    public float[] boxes() {
        return boxes;
    }

    /** Child links, eight per node (see the class comment); read-only. */
    public int[] children() {
        return children;
    }

    /** Primitive indices in leaf order: the binary tree's {@link Bvh#primitives()}; read-only. */
    public int[] primitives() {
        return primitives;
    }

    public int nodeCount() {
        return children.length / WIDTH;
    }

    /** Levels of wide nodes from the root to the deepest, the root counting as one. */
    public int depth() {
        return depth;
    }

    /** Whether a link names a leaf (not an interior node, not {@link #EMPTY}). */
    public static boolean isLeaf(int link) {
        return link < EMPTY;
    }

    /** A leaf link's first slot in {@link #primitives()}. */
    public static int leafFirst(int link) {
        return ~link >>> 3;
    }

    /** A leaf link's primitive count, 1 to {@link Bvh#LEAF_MAX}. */
    public static int leafCount(int link) {
        return ~link & 7;
    }

    /** The link of a leaf of {@code count} (1..{@link Bvh#LEAF_MAX}) primitives from slot {@code first}. */
    static int leaf(int first, int count) {
        return ~(first << 3 | count);
    }

    /** The largest float at most {@code v} (-infinity below the float range). */
    public static float floatBelow(double v) {
        float f = (float) v;
        return f > v ? Math.nextDown(f) : f;
    }

    /** The smallest float at least {@code v} (+infinity above the float range). */
    public static float floatAbove(double v) {
        float f = (float) v;
        return f < v ? Math.nextUp(f) : f;
    }
}

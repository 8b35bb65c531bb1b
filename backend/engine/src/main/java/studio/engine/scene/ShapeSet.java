package studio.engine.scene;

import java.util.Arrays;
import java.util.List;

import studio.engine.accel.Bvh;
import studio.engine.accel.PlaneLeaves;
import studio.engine.accel.ShapeLeaves;
import studio.engine.accel.Traversal;
import studio.engine.geometry.Frustum;
import studio.engine.geometry.Hit;
import studio.engine.geometry.LightBuffer;
import studio.engine.geometry.Ray;
import studio.engine.geometry.RayBundle;
import studio.engine.geometry.Shape;
import studio.engine.math.Vec3;
import studio.engine.memory.MemoryGate;

/**
 * A scene's shapes in declaration order, as one aggregate that answers two questions:
 * {@link #intersect} (the nearest hit, under {@link ShapeLeaves}' tie rule: of hits within
 * {@link Scene#TIE} the first-declared shape wins) and {@link #occluded} (any hit).
 *
 * <p>Up to {@value #LINEAR_MAX} shapes are tested one after the other; larger scenes put their
 * bounded shapes (spheres, boxes, meshes) into a {@link Bvh}, walked by the engine's one
 * {@link Traversal}, and test unbounded planes beside it. The threshold is measured
 * ({@code ShapeSetTiming} in the tests: with the objects small in the frame the BVH is faster from
 * 2 objects on, with the objects filling the frame from 5).
 *
 * <p>Behind {@link #occluded}, a set of at least {@value #LIGHT_BUFFER_MIN} bounded shapes made
 * with point lights keeps a {@link LightBuffer} for each of up to {@value LightBuffer#MAX_LIGHTS}
 * of them: a ray that ends at such a light tests the few shapes listed in its direction, nearest
 * the light first, and walks the tree only when the buffer leaves the ray to it; the same answer.
 * Behind {@link #intersect}, a ray of a {@link RayBundle} tests what the bundle's pyramid holds
 * ({@link BundleSearch}), and a ray that starts into a shape tests it first ({@link Ray#within});
 * behind {@link #occluded}, the shape that last blocked the ray object is tested first
 * ({@link Ray#blocker}), then a shadow ray of a {@link RayBundle} tests what its pyramid holds.
 *
 * <p>A set made from the last one ({@link #of(List, Shape[], ShapeSet)}: a live view's next
 * revision, its shapes the last one's but a few) refits that one's tree ({@link ShapeTree}) and
 * keeps its light buffers, testing the changed shapes beside them ({@link StaleSlots}).
 */
public final class ShapeSet {

    /** Scenes with at most this many shapes use the linear loop. */
    public static final int LINEAR_MAX = 4;
    /** Scenes with fewer bounded shapes than this have no light buffers: their tree is cheap. */
    public static final int LIGHT_BUFFER_MIN = 64;
    /** {@link #apartMargin} as a fraction of the scene's largest coordinate. */
    static final double APART_MARGIN = 1e-7;
    private static final byte UNKNOWN = 0, APART = 1, NEAR = 2;
    /** A ray ends at a buffered light if its end lies within this fraction of its length of it (shadow rays stop 1e-9 short). */
    private static final double AT_LIGHT = 1e-6;

    private final int size;
    /** Per shape (by its index among all the shapes), whether it is in this set; null: all are. */
    private final boolean[] members;
    /** Linear: every shape, slot = index. With a tree: none. */
    private final ShapeLeaves listed;
    private final int listedCount;
    /** With a tree: the planes. Linear: none. */
    private final PlaneLeaves planes;
    private final int planeCount;
    /** The tree over the bounded shapes, or null (linear). */
    private final Traversal tree;
    private final ShapeLeaves bounded;
    /** The tree's node boxes and links (null: linear), for {@link #nothingNear}. */
    private final double[] nodeBounds;
    private final int[] nodeLinks;
    /** Per shape (by its index among all the shapes), its slot in the tree, or -1: unbounded, or not a member. */
    private final int[] slotOfShape;
    /** Per slot, its shape's box (six doubles). */
    private final double[] slotBoxes;
    /**
     * Per slot, whether its shape stands apart: {@link #UNKNOWN} until first asked, then
     * {@link #APART} or {@link #NEAR} ({@link #standsApart}); any thread may work it out, and every
     * thread works out the same answer.
     */
    private final byte[] slotApart;
    /** How far beyond a shape's box a segment may reach and still count as inside it; twice this, no other box may come. */
    private final double apartMargin;
    /** Camera rays' bundles (null: the set is too small for lists to pay, or has no tree). */
    private final BundleSearch bundles;
    /** Whether shadow rays' bundles are listed too: where no light buffer answers them instead. */
    private final boolean shadowBundles;
    /** Per light, a light buffer over the tree's slots, or null. */
    private final LightBuffer[] lightBuffers;
    /** The lights the set was made with (a null: one with a size). */
    private final List<Vec3> lights;
    /** The tree's slots, node boxes and planes (null: linear), which the next set may refit. */
    private final ShapeTree shapeTree;
    /**
     * Slots whose shapes changed since the light buffers were built: the buffers may list them
     * where they were, so a shadow ray the buffers find nothing on tests these too ({@link StaleSlots}).
     */
    private final int[] staleSlots;
    /** Answers {@link #nothingIn}. */
    private final PyramidSearch pyramids;

    ShapeSet(Shape[] shapes, boolean useBvh, List<Vec3> lights) {
        this(shapes, null, useBvh, lights, null);
    }

    /**
     * Shapes i with {@code members[i]} (all if null), reporting hits by their index among all the
     * shapes; with a tree refitted from {@code last}'s ({@link ShapeTree#refit}) where it has one over
     * the same members and as many shapes, and its light buffers kept where its lights are these.
     */
    private ShapeSet(Shape[] shapes, boolean[] members, boolean useBvh, List<Vec3> lights, ShapeSet last) {
        Shape[] all = shapes.clone();
        this.members = members;
        this.lights = lights;
        // a refit keeps every shape bounded or not as it was, so the counts are the last set's
        ShapeTree refitted = useBvh && last != null && last.shapeTree != null && Arrays.equals(members, last.members)
                ? last.shapeTree.refit(all, members) : null;
        int memberCount = refitted != null ? last.size : 0;
        int boundedCount = refitted != null ? refitted.slotShapes.length : 0;
        for (int i = 0; i < all.length && refitted == null; i++) {
            if (members == null || members[i]) {
                memberCount++;
                boundedCount += all[i].bounds().isBounded() ? 1 : 0;
            }
        }
        size = memberCount;
        if (!useBvh || boundedCount == 0) {
            int[] listedIndex = new int[memberCount];
            for (int i = 0, n = 0; i < all.length; i++) {
                if (members == null || members[i]) {
                    listedIndex[n++] = i;
                }
            }
            listed = new ShapeLeaves(all, listedIndex);
            listedCount = memberCount;
            planes = new PlaneLeaves(all, new int[0]);
            planeCount = 0;
            shapeTree = null;
            tree = null;
            bounded = null;
            nodeBounds = null;
            nodeLinks = null;
            slotOfShape = null;
            slotBoxes = null;
            slotApart = null;
            apartMargin = 0;
            bundles = null;
            shadowBundles = false;
            lightBuffers = new LightBuffer[0];
            staleSlots = new int[0];
            pyramids = new PyramidSearch(all, null, null, new int[0], 0, listedIndex);
            return;
        }
        shapeTree = refitted != null ? refitted : ShapeTree.build(all, members);
        nodeBounds = shapeTree.nodeBounds;
        nodeLinks = shapeTree.nodeLinks;
        slotOfShape = shapeTree.slotOfShape;
        slotBoxes = shapeTree.slotBoxes;
        double largest = shapeTree.largest();
        slotApart = new byte[boundedCount];
        apartMargin = Math.max(APART_MARGIN * largest, Double.MIN_NORMAL);
        listed = new ShapeLeaves(all, new int[0]);
        listedCount = 0;
        planes = new PlaneLeaves(all, shapeTree.planeIndex);
        planeCount = shapeTree.planeIndex.length;
        bounded = new ShapeLeaves(all, shapeTree.slotShapes);
        tree = new Traversal(nodeBounds, nodeLinks, bounded);
        pyramids = new PyramidSearch(all, tree, slotBoxes, slotOfShape, largest, shapeTree.planeIndex);
        bundles = BundleSearch.pays(memberCount, planeCount) ? new BundleSearch(tree, bounded, shapeTree.slotShapes,
                slotBoxes, planes, shapeTree.planeIndex, largest, all) : null;
        LightBuffer.Primitives slots = (slot, ray, tMax) -> bounded.any(slot, slot + 1, ray, tMax);
        int[] stale = refitted != null && last.lights.equals(this.lights)
                ? StaleSlots.union(last.staleSlots, refitted.changedSlots) : null;
        if (stale != null) {
            staleSlots = stale;
            lightBuffers = new LightBuffer[last.lightBuffers.length];
            for (int i = 0; i < lightBuffers.length; i++) {
                lightBuffers[i] = last.lightBuffers[i] == null ? null : last.lightBuffers[i].testing(slots);
            }
            shadowBundles = bundles != null && lightBuffers.length == 0;
            return;
        }
        staleSlots = new int[0];
        int buffered = boundedCount >= LIGHT_BUFFER_MIN ? Math.min(lights.size(), LightBuffer.MAX_LIGHTS) : 0;
        lightBuffers = new LightBuffer[buffered];
        for (int i = 0; i < buffered; i++) {
            // null: a light with a size, whose shadow rays end all over it, so no one point's buffer serves
            lightBuffers[i] = lights.get(i) == null ? null
                    : LightBuffer.ofBoxes(slotBoxes, boundedCount, shapeTree.rootBounds(), lights.get(i),
                            slots, MemoryGate.UNLIMITED);
        }
        shadowBundles = bundles != null && buffered == 0;
    }

    /** The shapes, searched linearly or through a BVH depending on their number. */
    public static ShapeSet of(Shape... shapes) {
        return of(List.of(), shapes);
    }

    /**
     * The shapes, with a light buffer for each of the first {@value LightBuffer#MAX_LIGHTS} of
     * these point lights that can have one, in sets of at least {@value #LIGHT_BUFFER_MIN} bounded
     * shapes. A null light (one with a size) keeps its index and has no buffer.
     */
    public static ShapeSet of(List<Vec3> lights, Shape... shapes) {
        return new ShapeSet(shapes, shapes.length > LINEAR_MAX, lights);
    }

    /**
     * As {@link #of(List, Shape...)}, reusing {@code last}'s tree (null: none) where the shapes are
     * as many and all but a few the very objects of its set: the same answers, without building a
     * tree ({@link ShapeTree}).
     */
    public static ShapeSet of(List<Vec3> lights, Shape[] shapes, ShapeSet last) {
        return new ShapeSet(shapes, null, shapes.length > LINEAR_MAX, lights, last);
    }

    /**
     * Of the shapes, those i with {@code members[i]}, as {@link #of(List, Shape...)} makes a set of
     * them, or always through a tree if {@code tree}; hits report a shape's index among all the shapes.
     */
    public static ShapeSet of(List<Vec3> lights, Shape[] shapes, boolean[] members, boolean tree) {
        return of(lights, shapes, members, tree, null);
    }

    /** As {@link #of(List, Shape[], boolean[], boolean)}, reusing {@code last}'s tree as {@link #of(List, Shape[], ShapeSet)} does. */
    public static ShapeSet of(List<Vec3> lights, Shape[] shapes, boolean[] members, boolean tree, ShapeSet last) {
        int count = 0;
        for (boolean m : members) {
            count += m ? 1 : 0;
        }
        return new ShapeSet(shapes, members.clone(), tree || count > LINEAR_MAX, lights, last);
    }

    public int size() {
        return size;
    }

    /**
     * The nearest hit with 0 &lt; t &lt; tMax under the tie rule; sets {@code hit.primitive} to the
     * shape's index. A bounded shape the ray starts into ({@link Ray#within}) is tested first, which
     * lets the tree skip every node beyond its hit; when that shape stands apart and the ray's span
     * up to where a hit could still win lies in its box, nothing else bounded can be hit on it and
     * the tree is not walked at all. The same hit either way: one more visiting order.
     */
    public boolean intersect(Ray ray, double tMax, Hit hit) {
        RayBundle b = ray.bundle;
        if (b != null && bundles != null && b.fromApex() && bundles.lists(b, this)) {
            return bundles.intersect(ray, tMax, hit);
        }
        hit.primitive = ShapeLeaves.NONE;
        int likely = ray.within;
        int slot = tree != null && likely >= 0 && likely < slotOfShape.length ? slotOfShape[likely] : -1;
        double cull = slot >= 0 ? bounded.nearest(slot, slot + 1, ray, tMax, tMax, hit) : tMax;
        cull = listed.nearest(0, listedCount, ray, tMax, cull, hit);
        cull = planes.nearest(0, planeCount, ray, tMax, cull, hit);
        if (tree != null && !(slot >= 0 && hit.primitive != ShapeLeaves.NONE && alone(slot, ray, cull))) {
            tree.nearest(ray, tMax, cull, hit, hit.sceneStack, hit.sceneStackEntry, hit.sceneWide);
        }
        return hit.primitive != ShapeLeaves.NONE;
    }

    /**
     * Whether the ray's part from its origin to {@code end} lies in slot {@code slot}'s box, widened
     * by {@link #apartMargin}, and that slot {@link #standsApart}: then no other bounded shape can
     * be hit on it.
     */
    private boolean alone(int slot, Ray ray, double end) {
        return inBox(slot, ray.ox, ray.oy, ray.oz)
                && inBox(slot, ray.ox + end * ray.dx, ray.oy + end * ray.dy, ray.oz + end * ray.dz)
                && standsApart(slot);
    }

    /** Whether the point lies in slot {@code slot}'s box widened by {@link #apartMargin} (false for a NaN). */
    private boolean inBox(int slot, double x, double y, double z) {
        double[] b = slotBoxes;
        int o = 6 * slot;
        double m = apartMargin;
        return x >= b[o] - m && y >= b[o + 1] - m && z >= b[o + 2] - m
                && x <= b[o + 3] + m && y <= b[o + 4] + m && z <= b[o + 5] + m;
    }

    /**
     * Whether no other slot's box comes within twice {@link #apartMargin} of this slot's box
     * (touching counts as coming near). A segment inside this box widened by the margin then stays
     * further than the margin from every other bounded shape, far more than the rounding of any
     * intersection test (about 1e-15 of the coordinates), so none of them can report a hit on it.
     */
    private boolean standsApart(int slot) {
        byte known = slotApart[slot];
        if (known == UNKNOWN) {
            known = nothingNear(slot) ? APART : NEAR;
            slotApart[slot] = known;
        }
        return known == APART;
    }

    /** The tree searched for another slot whose box overlaps this slot's, widened by twice the margin. */
    private boolean nothingNear(int slot) {
        double m = 2 * apartMargin;
        int o = 6 * slot;
        double x0 = slotBoxes[o] - m, y0 = slotBoxes[o + 1] - m, z0 = slotBoxes[o + 2] - m;
        double x1 = slotBoxes[o + 3] + m, y1 = slotBoxes[o + 4] + m, z1 = slotBoxes[o + 5] + m;
        int node = 0, nodeCount = nodeLinks.length / 3;
        while (node < nodeCount) {
            int n = 6 * node, l = 3 * node;
            if (overlaps(nodeBounds, n, x0, y0, z0, x1, y1, z1)) {
                int count = nodeLinks[l + 1];
                if (count < 0) {
                    node++;
                    continue;
                }
                for (int s = nodeLinks[l], last = s + count; s < last; s++) {
                    if (s != slot && overlaps(slotBoxes, 6 * s, x0, y0, z0, x1, y1, z1)) {
                        return false;
                    }
                }
            }
            node = nodeLinks[l + 2];
        }
        return true;
    }

    private static boolean overlaps(double[] b, int o, double x0, double y0, double z0, double x1, double y1, double z1) {
        return b[o] <= x1 && b[o + 1] <= y1 && b[o + 2] <= z1 && b[o + 3] >= x0 && b[o + 4] >= y0 && b[o + 5] >= z0;
    }

    /**
     * Whether no shape of the set but shape {@code except} (-1: none) may lie in the pyramid, so
     * that nothing else can stop a segment inside it; conservative ({@link PyramidSearch}).
     * The pyramid must end; {@code reach} (six doubles) and {@code stack}
     * ({@link studio.engine.accel.Bvh#STACK_SIZE} ints) are the caller's scratch.
     */
    public boolean nothingIn(Frustum pyramid, int except, double[] reach, int[] stack) {
        return pyramids.nothingIn(pyramid, except, reach, stack);
    }

    /** Whether anything lies on the ray with 0 &lt; t &lt; tMax. */
    public boolean occluded(Ray ray, double tMax) {
        int last = ray.blocker;
        boolean member = last >= 0 && (members == null || last < members.length && members[last]);
        if (member && listed.blocks(last, ray, tMax)) {
            return true;
        }
        RayBundle b = ray.bundle;
        if (b != null && shadowBundles && !b.fromApex() && bundles.lists(b, this)) {
            return bundles.occluded(ray, tMax);
        }
        boolean blocked = listed.any(0, listedCount, ray, tMax) || planes.any(0, planeCount, ray, tMax)
                || tree != null && blockedInTree(ray, tMax);
        if (!blocked) {
            ray.blocker = -1;
        }
        return blocked;
    }

    /** Whether a bounded shape lies on the ray: through the light buffer of the light it ends at, if any, else the tree. */
    private boolean blockedInTree(Ray ray, double tMax) {
        LightBuffer buffer = bufferAtEnd(ray, tMax);
        int slot = buffer == null ? LightBuffer.UNDECIDED : buffer.occluder(ray, tMax);
        if (slot == LightBuffer.NONE) {
            return StaleSlots.block(staleSlots, bounded, ray, tMax);
        }
        return slot == LightBuffer.UNDECIDED ? tree.any(ray, tMax, ray.sceneWide()) : true;
    }

    /** The light buffer of the light the ray ends at, or null. */
    private LightBuffer bufferAtEnd(Ray ray, double tMax) {
        if (lightBuffers.length == 0) {
            return null;
        }
        double ex = ray.ox + ray.dx * tMax, ey = ray.oy + ray.dy * tMax, ez = ray.oz + ray.dz * tMax;
        double tolerance = AT_LIGHT * tMax;
        for (LightBuffer buffer : lightBuffers) {
            if (buffer != null && buffer.isAt(ex, ey, ez, tolerance)) {
                return buffer;
            }
        }
        return null;
    }
}

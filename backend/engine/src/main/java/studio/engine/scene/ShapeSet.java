package studio.engine.scene;

import java.util.Arrays;
import java.util.List;

import studio.engine.accel.Aabb;
import studio.engine.accel.Bvh;
import studio.engine.accel.Slab;
import studio.engine.geometry.Frustum;
import studio.engine.geometry.Hit;
import studio.engine.geometry.LightBuffer;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Shape;
import studio.engine.geometry.Sphere;
import studio.engine.math.Vec3;
import studio.engine.memory.MemoryGate;

/**
 * A scene's shapes in declaration order, searched for the nearest hit under the tie rule: of hits
 * within {@link Scene#TIE} of each other the first-declared shape wins, so coincident surfaces
 * never speckle (robustness case NUM-12, docs/robustness.md).
 *
 * <p>Up to {@value #LINEAR_MAX} shapes are tested one after the other; larger scenes put their
 * bounded shapes (spheres, boxes, meshes) into a {@link Bvh} and test unbounded planes beside it.
 * The threshold is measured ({@code ShapeSetTiming} in the tests: a floor plane with spheres and
 * boxes, primary plus shadow ray): with the objects small in the frame the BVH is faster from 2
 * objects on, since its box test is cheaper than a sphere or box test; with the objects filling
 * the frame the linear loop is faster up to 4 objects and the BVH from 5.
 *
 * <p>A BVH meets shapes out of declaration order, so it cannot simply shrink tMax as the linear
 * loop does. Instead, shape i is asked for hits before {@code best*(1 - TIE)} if it was declared
 * after the current best, and before {@code best*(1 + TIE)} if declared before it, and every hit it
 * then reports wins. For hits that form separate clusters (every pair within TIE inside one, and
 * clusters further apart than that) the lowest index of the nearest cluster wins in any visiting
 * order, as in the linear loop; only chains of near-ties spread over more than TIE can resolve
 * differently.
 *
 * <p>The BVH's leaves keep each sphere's centre and radius in a flat array by leaf slot and test
 * it through {@link Sphere}'s static test, which the record itself calls, so the hit is the same to
 * the bit; other shapes are asked through {@link Shape}. This spares a call through the interface
 * (megamorphic once spheres, boxes and meshes share a tree) and two dependent loads per sphere
 * (record, then its centre); measured by the kernel benchmark ({@code studio-bench.jar kernel}).
 *
 * <p>A ray that most likely ends on one shape (refracted into a glass object, or reflected inside
 * it; {@link #intersect(Ray, double, Hit, int)}) tests that shape first. If the shape stands apart
 * (no other shape's box comes near its own, {@link #standsApart}) and the ray, from its origin to
 * where a hit could still win, stays inside the shape's box, no other bounded shape can be hit on
 * the way, and the tree is not searched at all: the same hit, found with one test instead of the
 * shape's test, a walk down the tree and the same test again in its leaf (glass at 16 samples
 * 0.88 of the time in {@code studio-bench.jar peers}; docs/speed.md).
 *
 * <p>A bundle of rays inside one pyramid (a pixel's camera rays, or their shadow rays to a light)
 * can instead list the few shapes in the pyramid once ({@link #candidates}) and test only those:
 * a camera ray nearest first, stopping where the rest lie beyond its best hit
 * ({@link #orderByDistance}, {@link #intersectNearFirst}), a shadow ray until one lies on its way
 * ({@link #occluderAmong}); see {@code PixelCandidates}.
 *
 * <p>Made with the scene's lights, a set of at least {@value #LIGHT_BUFFER_MIN} bounded shapes
 * keeps a {@link LightBuffer} over its tree's slots for each of up to {@value LightBuffer#MAX_LIGHTS}
 * of them: a shadow ray towards such a light ({@link #occluderTowards}) tests the planes, then the
 * few shapes listed in its direction, nearest the light first, and searches the tree only when the
 * buffer leaves the ray to it (8,000 spheres over a floor: 0.68 of the time warm).
 */
public final class ShapeSet {

    /** Scenes with at most this many shapes use the linear loop. */
    public static final int LINEAR_MAX = 4;
    /**
     * Scenes with fewer bounded shapes than this have no light buffers: their pixel lists and tree
     * are cheap (the training scene's 76 get them; glass-pattern's 15 do not).
     */
    public static final int LIGHT_BUFFER_MIN = 64;
    /** {@link #apartMargin} as a fraction of the scene's largest coordinate. */
    static final double APART_MARGIN = 1e-7;
    /** {@link #orderByDistance}'s distances are shrunk by this factor: far more than their rounding (about 1e-15). */
    private static final double NEAR_SHRINK = 1 - 1e-7;

    private final Shape[] shapes;
    /** How many of the shapes are unbounded (planes). */
    private final int unboundedCount;
    /** Indices of the unbounded shapes, ascending; null in linear mode. */
    private final int[] unbounded;
    /** The BVH over the bounded shapes (leaf slots hold shape indices), or null. */
    private final double[] nodeBounds;
    private final int[] nodeLinks;
    private final int[] leafShapes;
    /**
     * Per leaf slot, a sphere's centre and radius (four doubles), tested in the traversal loops
     * through {@link Sphere}'s static tests without a call through {@link Shape} or a load of its
     * centre; radius 0 marks a slot whose shape is not a sphere and is asked through {@link Shape}.
     */
    private final double[] leafSpheres;
    /** Per shape, its leaf slot, or -1 for an unbounded shape; null in linear mode. */
    private final int[] slotOfShape;
    /** Per leaf slot, its shape's box (six doubles); null in linear mode. */
    private final double[] slotBoxes;
    private final int nodeCount;
    /** The largest absolute coordinate of the BVH's root box: of every box in the tree. */
    private final double magnitude;
    /**
     * Per leaf slot, whether its shape stands apart: {@link #UNKNOWN} until first asked, then
     * {@link #APART} or {@link #NEAR} (see {@link #standsApart}). Worked out when a search first
     * needs it, by any thread: every thread works out the same answer.
     */
    private final byte[] slotApart;
    /** How far beyond a shape's box a segment may reach and still count as inside it; twice this, no other box may come. */
    private final double apartMargin;
    /** Per light, a light buffer over the tree's slots, or null (see {@link #occluderTowards}). */
    private final LightBuffer[] lightBuffers;

    private static final byte UNKNOWN = 0, APART = 1, NEAR = 2;

    ShapeSet(Shape[] shapes, boolean useBvh, List<Vec3> lights) {
        this.shapes = shapes.clone();
        int boundedCount = 0;
        for (Shape s : shapes) {
            if (s.bounds().isBounded()) {
                boundedCount++;
            }
        }
        unboundedCount = shapes.length - boundedCount;
        if (!useBvh || boundedCount == 0) {
            unbounded = null;
            nodeBounds = null;
            nodeLinks = null;
            leafShapes = null;
            leafSpheres = null;
            slotOfShape = null;
            slotBoxes = null;
            nodeCount = 0;
            magnitude = 0;
            slotApart = null;
            apartMargin = 0;
            lightBuffers = new LightBuffer[0];
            return;
        }
        int[] boundedIndex = new int[boundedCount];
        int[] unboundedIndex = new int[shapes.length - boundedCount];
        double[] boxes = new double[6 * boundedCount];
        int b = 0, u = 0;
        for (int i = 0; i < shapes.length; i++) {
            Aabb box = shapes[i].bounds();
            if (box.isBounded()) {
                box.copyTo(boxes, 6 * b);
                boundedIndex[b++] = i;
            } else {
                unboundedIndex[u++] = i;
            }
        }
        Bvh bvh = Bvh.build(boxes, boundedCount);
        int[] order = bvh.primitives();
        leafShapes = new int[boundedCount];
        leafSpheres = new double[4 * boundedCount];
        slotOfShape = new int[shapes.length];
        slotBoxes = new double[6 * boundedCount];
        Arrays.fill(slotOfShape, -1);
        for (int slot = 0; slot < boundedCount; slot++) {
            leafShapes[slot] = boundedIndex[order[slot]];
            slotOfShape[leafShapes[slot]] = slot;
            System.arraycopy(boxes, 6 * order[slot], slotBoxes, 6 * slot, 6);
            if (shapes[leafShapes[slot]] instanceof Sphere sphere) {
                leafSpheres[4 * slot] = sphere.center().x();
                leafSpheres[4 * slot + 1] = sphere.center().y();
                leafSpheres[4 * slot + 2] = sphere.center().z();
                leafSpheres[4 * slot + 3] = sphere.radius();
            }
        }
        unbounded = unboundedIndex;
        nodeBounds = bvh.bounds();
        nodeLinks = bvh.nodes();
        nodeCount = bvh.nodeCount();
        double largest = 0;
        for (int k = 0; k < 6; k++) {
            largest = Math.max(largest, Math.abs(nodeBounds[k]));
        }
        magnitude = largest;
        slotApart = new byte[boundedCount];
        apartMargin = Math.max(APART_MARGIN * largest, Double.MIN_NORMAL);
        int buffered = boundedCount >= LIGHT_BUFFER_MIN ? Math.min(lights.size(), LightBuffer.MAX_LIGHTS) : 0;
        lightBuffers = new LightBuffer[buffered];
        if (buffered > 0) {
            Aabb root = new Aabb(nodeBounds[0], nodeBounds[1], nodeBounds[2], nodeBounds[3], nodeBounds[4],
                    nodeBounds[5]);
            LightBuffer.Primitives slots = (slot, ray, tMax) -> occluded(leafShapes[slot], slot, ray, tMax);
            for (int i = 0; i < buffered; i++) {
                // null: a light with a size, whose shadow rays end all over it, so no one point's buffer serves
                lightBuffers[i] = lights.get(i) == null ? null : LightBuffer.ofBoxes(slotBoxes, boundedCount, root,
                        lights.get(i), slots, MemoryGate.UNLIMITED);
            }
        }
    }

    /** The shapes, searched linearly or through a BVH depending on their number. */
    public static ShapeSet of(Shape... shapes) {
        return of(List.of(), shapes);
    }

    /**
     * The shapes, with a light buffer ({@link LightBuffer}) over the tree for each of the first
     * {@value LightBuffer#MAX_LIGHTS} of these lights that can have one, in scenes of at least
     * {@value #LIGHT_BUFFER_MIN} bounded shapes: {@link #occluderTowards} then asks it. A null
     * light (one with a size) keeps its index and has no buffer.
     */
    public static ShapeSet of(List<Vec3> lights, Shape... shapes) {
        return new ShapeSet(shapes, shapes.length > LINEAR_MAX, lights);
    }

    public boolean usesBvh() {
        return nodeBounds != null;
    }

    public int size() {
        return shapes.length;
    }

    /** How many shapes have no bounds (planes): every {@link #candidates} list holds them. */
    public int unboundedCount() {
        return unboundedCount;
    }

    /** The nearest hit with 0 &lt; t &lt; tMax under the tie rule; sets {@code hit.primitive} to the shape's index. */
    public boolean intersect(Ray ray, double tMax, Hit hit) {
        return nodeBounds == null ? intersectLinear(ray, tMax, hit) : intersectBvh(ray, tMax, hit, -1);
    }

    /**
     * {@link #intersect(Ray, double, Hit)}, testing shape {@code likely} first (-1: none), which lets
     * the BVH skip every node beyond its hit. The same hit: it is one more visiting order.
     */
    public boolean intersect(Ray ray, double tMax, Hit hit, int likely) {
        return nodeBounds == null ? intersectLinear(ray, tMax, hit) : intersectBvh(ray, tMax, hit, likely);
    }

    /** Whether anything lies on the ray with 0 &lt; t &lt; tMax. */
    public boolean occluded(Ray ray, double tMax) {
        return occluder(ray, tMax) >= 0;
    }

    /** The index of a shape that lies on the ray with 0 &lt; t &lt; tMax (the first one found), or -1 if none does. */
    public int occluder(Ray ray, double tMax) {
        return nodeBounds == null ? occluderLinear(ray, tMax) : occluderBvh(ray, tMax);
    }

    /** Shape i's leaf slot, or -1 for an unbounded shape or a set without a tree (for tests). */
    int slotOf(int i) {
        return slotOfShape == null ? -1 : slotOfShape[i];
    }

    /**
     * {@link #occluder} for a shadow ray towards light {@code light} (its index among the lights
     * this set was made with): through that light's buffer where there is one, the planes first.
     * Whether some shape is found is the same answer; which one may differ.
     */
    public int occluderTowards(int light, Ray ray, double tMax) {
        LightBuffer buffer = light < lightBuffers.length ? lightBuffers[light] : null;
        if (buffer == null) {
            return occluder(ray, tMax);
        }
        for (int i : unbounded) {
            if (shapes[i].occluded(ray, tMax)) {
                return i;
            }
        }
        int slot = buffer.occluder(ray, tMax);
        return slot >= 0 ? leafShapes[slot] : slot == LightBuffer.NONE ? -1 : occluderBvh(ray, tMax);
    }

    /** How many light buffers the set has (for tests). */
    int lightBufferCount() {
        int n = 0;
        for (LightBuffer b : lightBuffers) {
            n += b != null ? 1 : 0;
        }
        return n;
    }

    /** Whether shape i lies on the ray with 0 &lt; t &lt; tMax: the test {@link #occluded} makes of it. */
    public boolean occludes(int i, Ray ray, double tMax) {
        return shapes[i].occluded(ray, tMax);
    }

    /**
     * Into {@code out}, ascending: the indices of the shapes a ray inside the frustum can hit, the
     * unbounded ones and those whose BVH leaves reach into it. Returns how many, or -1 when they
     * would not fit in {@code out}, or when this set has no BVH (its linear loop is as quick).
     * {@code stack} needs {@link Bvh#STACK_SIZE} ints.
     */
    public int candidates(Frustum frustum, int[] out, int[] stack) {
        if (nodeBounds == null || unbounded.length > out.length) {
            return -1;
        }
        frustum.within(magnitude);
        int n = 0;
        for (int i : unbounded) {
            out[n++] = i;
        }
        double[] nb = nodeBounds;
        int[] links = nodeLinks;
        int sp = 0, node = 0;
        while (true) {
            if (frustum.mayMeet(nb, 6 * node)) {
                int o = 3 * node;
                int count = links[o + 1];
                if (count < 0) {
                    stack[sp++] = links[o];
                    node++;
                    continue;
                }
                for (int slot = links[o], end = slot + count; slot < end; slot++) {
                    if (count == 1 || frustum.mayMeet(slotBoxes, 6 * slot)) {
                        if (n == out.length) {
                            return -1;
                        }
                        out[n++] = leafShapes[slot];
                    }
                }
            }
            if (sp == 0) {
                break;
            }
            node = stack[--sp];
        }
        for (int i = 1; i < n; i++) {
            int v = out[i], j = i - 1;
            while (j >= 0 && out[j] > v) {
                out[j + 1] = out[j];
                j--;
            }
            out[j + 1] = v;
        }
        return n;
    }

    /**
     * Orders shapes {@code ids[0 .. count-1]} by how near rays from (px, py, pz) could first hit
     * them, nearest first, and puts into {@code near[k]} a bound below every unit-length ray's hit
     * distance on shape {@code ids[k]}: its box's distance from the point (a hit lies in the box,
     * which is padded for the shape's rounding), shrunk by {@link #NEAR_SHRINK} for the rounding
     * of that distance and of the hit's t, and 0 for an unbounded shape.
     */
    public void orderByDistance(int[] ids, int count, double px, double py, double pz, double[] near) {
        for (int k = 0; k < count; k++) {
            int id = ids[k], slot = slotOfShape[id];
            double d = slot >= 0 ? Aabb.distance(slotBoxes, 6 * slot, px, py, pz) * NEAR_SHRINK : 0;
            int j = k - 1;
            while (j >= 0 && near[j] > d) {
                near[j + 1] = near[j];
                ids[j + 1] = ids[j];
                j--;
            }
            near[j + 1] = d;
            ids[j + 1] = id;
        }
    }

    /**
     * {@link #intersect} for a unit-length ray that can hit only the shapes {@code ids[0 .. count-1]},
     * ordered by {@link #orderByDistance} from its origin: tested nearest first, as the tree's
     * search visits its nodes, and no further once the next one's bound lies beyond where a hit
     * could still win. The tie rule is the tree's (see the class comment), so the hit is the one
     * {@link #intersect} finds, as any visiting order finds it, except in chains of near-ties
     * spread over more than {@link Scene#TIE}.
     */
    public boolean intersectNearFirst(int[] ids, double[] near, int count, Ray ray, double tMax, Hit hit) {
        double best = tMax, cull = tMax;
        int winner = Integer.MAX_VALUE;
        for (int k = 0; k < count && near[k] <= cull; k++) {
            int i = ids[k];
            if (intersect(i, slotOfShape[i], ray, limit(i, winner, best, tMax), hit)) {
                best = hit.t;
                winner = i;
                cull = Math.min(tMax, best * (1 + Scene.TIE));
            }
        }
        if (winner == Integer.MAX_VALUE) {
            return false;
        }
        hit.primitive = winner;
        return true;
    }

    /**
     * Into {@code box[0 .. 5]}: a box holding every point where a ray inside {@code cameraRays} can
     * hit one of shapes {@code ids[0 .. count-1]} (from {@link #candidates} with that pyramid): the
     * union of the parts of their boxes inside the pyramid ({@link Frustum#widenToPart}), and for a
     * plane its part inside it ({@link Frustum#widenToPlane}). False when a plane's part is
     * unbounded, when the pyramid has an end (it is not a camera's), or when nothing can be hit.
     */
    public boolean boundsOf(int[] ids, int count, Frustum cameraRays, double[] box) {
        box[0] = box[1] = box[2] = Double.POSITIVE_INFINITY;
        box[3] = box[4] = box[5] = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < count; k++) {
            int slot = slotOfShape[ids[k]];
            if (slot < 0) {
                if (!(shapes[ids[k]] instanceof Plane plane)) {
                    return false;
                }
                Vec3 p = plane.point(), n = plane.normal();
                if (!cameraRays.widenToPlane(p.x(), p.y(), p.z(), n.x(), n.y(), n.z(), box)) {
                    return false;
                }
                continue;
            }
            cameraRays.widenToPart(slotBoxes, 6 * slot, box); // an ended pyramid leaves the box empty
        }
        return box[0] <= box[3] && box[1] <= box[4] && box[2] <= box[5];
    }

    /**
     * {@link #occluder} for a ray that can meet only the shapes {@code ids[0 .. count-1]} (from
     * {@link #candidates}): the first of them that lies on the ray, or -1.
     */
    public int occluderAmong(int[] ids, int count, Ray ray, double tMax) {
        for (int k = 0; k < count; k++) {
            int i = ids[k];
            if (occluded(i, slotOfShape[i], ray, tMax)) {
                return i;
            }
        }
        return -1;
    }

    /**
     * Shape i, at leaf slot {@code slot} (-1: not in the tree), asked for a hit before limit: a
     * sphere through the slot's centre and radius, any other shape through {@link Shape}.
     */
    private boolean intersect(int i, int slot, Ray ray, double limit, Hit hit) {
        int k = 4 * slot;
        double[] spheres = leafSpheres;
        return slot >= 0 && spheres[k + 3] != 0
                ? Sphere.intersect(spheres[k], spheres[k + 1], spheres[k + 2], spheres[k + 3], ray, limit, hit)
                : shapes[i].intersect(ray, limit, hit);
    }

    /** {@link #intersect(int, int, Ray, double, Hit)}'s any-hit question. */
    private boolean occluded(int i, int slot, Ray ray, double tMax) {
        int k = 4 * slot;
        double[] spheres = leafSpheres;
        return slot >= 0 && spheres[k + 3] != 0
                ? Sphere.occluded(spheres[k], spheres[k + 1], spheres[k + 2], spheres[k + 3], ray, tMax)
                : shapes[i].occluded(ray, tMax);
    }

    private boolean intersectLinear(Ray ray, double tMax, Hit hit) {
        boolean found = false;
        double limit = tMax;
        for (int i = 0; i < shapes.length; i++) {
            if (shapes[i].intersect(ray, limit, hit)) {
                found = true;
                hit.primitive = i;
                limit = hit.t * (1 - Scene.TIE);
            }
        }
        return found;
    }

    private int occluderLinear(Ray ray, double tMax) {
        for (int i = 0; i < shapes.length; i++) {
            if (shapes[i].occluded(ray, tMax)) {
                return i;
            }
        }
        return -1;
    }

    private boolean intersectBvh(Ray ray, double tMax, Hit hit, int likely) {
        // best = t of the current winner, winner = its index (MAX_VALUE: none yet).
        double best = tMax;
        int winner = Integer.MAX_VALUE;
        if (likely >= 0 && intersect(likely, slotOfShape[likely], ray, tMax, hit)) {
            best = hit.t;
            winner = likely;
        }
        for (int i : unbounded) {
            if (shapes[i].intersect(ray, limit(i, winner, best, tMax), hit)) {
                best = hit.t;
                winner = i;
            }
        }
        // Any shape may still win a tie up to best*(1+TIE), so nodes are culled only beyond that.
        double cull = winner == Integer.MAX_VALUE ? tMax : Math.min(tMax, best * (1 + Scene.TIE));
        if (winner != Integer.MAX_VALUE && likely >= 0 && alone(likely, ray, cull)) {
            hit.primitive = winner;
            return true;
        }
        double ox = ray.ox, oy = ray.oy, oz = ray.oz;
        double ix = 1 / ray.dx, iy = 1 / ray.dy, iz = 1 / ray.dz;
        boolean nanFree = Slab.nanFree(ox, oy, oz, ix, iy, iz);
        double[] nb = nodeBounds;
        int[] links = nodeLinks;
        int[] stack = hit.sceneStack;
        double[] stackEntry = hit.sceneStackEntry;
        int sp = 0, node = 0;
        double entry = Slab.entry(nb, 0, ox, oy, oz, ix, iy, iz, nanFree, cull);
        while (true) {
            if (entry <= cull) {
                int o = 3 * node;
                int count = links[o + 1];
                if (count < 0) {
                    // both children's boxes are tested here: the nearer is visited first, the other
                    // waits on the stack with its entry distance, and a child the ray misses is never pushed
                    int left = node + 1, right = links[o];
                    double inLeft = Slab.entry(nb, 6 * left, ox, oy, oz, ix, iy, iz, nanFree, cull);
                    double inRight = Slab.entry(nb, 6 * right, ox, oy, oz, ix, iy, iz, nanFree, cull);
                    boolean hitLeft = inLeft <= cull, hitRight = inRight <= cull; // a miss is NaN: false
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
                        int i = leafShapes[slot];
                        if (intersect(i, slot, ray, limit(i, winner, best, tMax), hit)) {
                            best = hit.t;
                            winner = i;
                            cull = Math.min(tMax, best * (1 + Scene.TIE));
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
        if (winner == Integer.MAX_VALUE) {
            return false;
        }
        hit.primitive = winner;
        return true;
    }

    /**
     * Whether the ray's part from its origin to {@code end} (where a hit could still win) lies in
     * bounded shape i's box, widened by {@link #apartMargin}, and i {@link #standsApart}: then no
     * other bounded shape can be hit on it, and the tree need not be searched.
     */
    private boolean alone(int i, Ray ray, double end) {
        int slot = slotOfShape[i];
        return slot >= 0 && inBox(slot, ray.ox, ray.oy, ray.oz)
                && inBox(slot, ray.ox + end * ray.dx, ray.oy + end * ray.dy, ray.oz + end * ray.dz)
                && standsApart(slot);
    }

    /** Whether the point lies in the box of slot {@code slot} widened by {@link #apartMargin} (false for a NaN). */
    private boolean inBox(int slot, double x, double y, double z) {
        double[] b = slotBoxes;
        int o = 6 * slot;
        double m = apartMargin;
        return x >= b[o] - m && y >= b[o + 1] - m && z >= b[o + 2] - m
                && x <= b[o + 3] + m && y <= b[o + 4] + m && z <= b[o + 5] + m;
    }

    /**
     * Whether no other slot's box comes within twice {@link #apartMargin} of this slot's box
     * (touching counts as coming near). A segment inside this box widened by the margin then
     * stays further than the margin from every other bounded shape, far more than the rounding of
     * any intersection test (about 1e-15 of the coordinates), so none of them can report a hit on
     * it. A glass object standing apart, as glass usually does, is the case this serves: a ray
     * refracted into it, or reflected inside it, needs only its own test (and the planes').
     */
    boolean standsApart(int slot) {
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
        int node = 0;
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

    /** Hits shape i must come before to win against the current winner (see the class comment). */
    private static double limit(int i, int winner, double best, double tMax) {
        if (winner == Integer.MAX_VALUE) {
            return tMax;
        }
        return i < winner ? Math.min(tMax, best * (1 + Scene.TIE)) : best * (1 - Scene.TIE);
    }

    private int occluderBvh(Ray ray, double tMax) {
        for (int i : unbounded) {
            if (shapes[i].occluded(ray, tMax)) {
                return i;
            }
        }
        double ox = ray.ox, oy = ray.oy, oz = ray.oz;
        double ix = 1 / ray.dx, iy = 1 / ray.dy, iz = 1 / ray.dz;
        boolean nanFree = Slab.nanFree(ox, oy, oz, ix, iy, iz);
        double[] nb = nodeBounds;
        int[] links = nodeLinks;
        int node = 0, end = nodeCount;
        while (node < end) {
            int o = 3 * node;
            if (Slab.hits(nb, 6 * node, ox, oy, oz, ix, iy, iz, nanFree, tMax)) {
                int count = links[o + 1];
                if (count < 0) {
                    node++;
                    continue;
                }
                for (int slot = links[o], last = slot + count; slot < last; slot++) {
                    if (occluded(leafShapes[slot], slot, ray, tMax)) {
                        return leafShapes[slot];
                    }
                }
            }
            node = links[o + 2];
        }
        return -1;
    }
}

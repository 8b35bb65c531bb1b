package studio.engine.scene;

import java.util.Arrays;

import studio.engine.accel.Aabb;
import studio.engine.accel.PlaneLeaves;
import studio.engine.accel.ShapeLeaves;
import studio.engine.accel.Traversal;
import studio.engine.geometry.Frustum;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.RayBundle;
import studio.engine.geometry.Shape;
import studio.engine.math.Vec3;

/**
 * {@link ShapeSet#intersect} for a ray that carries a {@link RayBundle}: the shapes inside the
 * bundle's pyramid are listed once ({@link Traversal#slotsIn}, the planes always), ordered by
 * how near the apex their boxes come, and each ray tests them nearest first, stopping where the
 * next one lies beyond where a hit could still win, as the tree's walk skips the boxes beyond.
 * A ray can hit only what lies in its pyramid, and the tie rule picks the same winner in any
 * order of testing, so the hit is the tree's (but for chains of near-ties spread over more than
 * {@link Scene#TIE}). Where camera rays pass between many objects deep into the tree and a
 * pixel's rays meet the same few, this spares most of the walk (5,000 small spheres, warm, one
 * thread, 16 samples: about half the time).
 *
 * <p>A shadow bundle (the rays from where a camera bundle's rays hit one object to a point light)
 * gets its pyramid here, from the light over the part of that object's box, or plane, inside the
 * camera rays' pyramid ({@link Frustum#widenToPart}, {@link Frustum#widenToPlane}); its list is
 * not ordered, and {@link #occluded} tests each of its rays against it whole.
 */
final class BundleSearch {

    /** Fewest shapes for which listing pays (a small tree leaves little to save: still life, 6, 1.09 of the time with lists). */
    static final int MIN_SHAPES = 8;

    /**
     * Whether lists pay for a set of this many shapes, this many of them planes (in every list):
     * from {@link #MIN_SHAPES} on, with fewer planes than log2 of the shapes (a ray's walk tests
     * about that many levels; mirror-room's 6 planes among 8 shapes: 1.13 of the time with lists).
     */
    static boolean pays(int shapes, int planes) {
        return shapes >= MIN_SHAPES && planes < 31 - Integer.numberOfLeadingZeros(shapes);
    }
    /** {@link #order}'s distances are shrunk by this factor: far more than their rounding (about 1e-15). */
    private static final double NEAR_SHRINK = 1 - 1e-7;

    private final Traversal tree;
    private final ShapeLeaves bounded;
    private final PlaneLeaves planes;
    private final int[] planeIndex, slotShapes;
    private final double[] slotBoxes;
    private final double magnitude;
    /** Per plane, its point and normal (six doubles). */
    private final double[] planeFrames;
    /** Per shape (by declaration index), its slot, a plane k as {@code ~k}, or {@link #NOT_HERE}. */
    private final int[] idOfShape;
    private static final int NOT_HERE = Integer.MIN_VALUE;

    /** The search over a set's tree, its planes ({@code shapes[planeIndex[k]]}) beside it. */
    BundleSearch(Traversal tree, ShapeLeaves bounded, int[] slotShapes, double[] slotBoxes, PlaneLeaves planes,
                 int[] planeIndex, double magnitude, Shape[] shapes) {
        this.tree = tree;
        this.bounded = bounded;
        this.slotShapes = slotShapes;
        this.slotBoxes = slotBoxes;
        this.planes = planes;
        this.planeIndex = planeIndex;
        this.magnitude = magnitude;
        this.idOfShape = new int[shapes.length];
        Arrays.fill(idOfShape, NOT_HERE);
        for (int slot = 0; slot < slotShapes.length; slot++) {
            idOfShape[slotShapes[slot]] = slot;
        }
        this.planeFrames = new double[6 * planeIndex.length];
        for (int k = 0; k < planeIndex.length; k++) {
            idOfShape[planeIndex[k]] = ~k;
            Plane plane = (Plane) shapes[planeIndex[k]];
            Vec3 p = plane.point(), n = plane.normal();
            planeFrames[6 * k] = p.x();
            planeFrames[6 * k + 1] = p.y();
            planeFrames[6 * k + 2] = p.z();
            planeFrames[6 * k + 3] = n.x();
            planeFrames[6 * k + 4] = n.y();
            planeFrames[6 * k + 5] = n.z();
        }
    }

    /** Whether the bundle holds a list for {@code owner} (made now if need be): false when its pyramid holds too many shapes. */
    boolean lists(RayBundle b, Object owner) {
        if (b.listedBy != owner) {
            list(b);
            b.listedBy = owner;
        }
        return b.count >= 0;
    }

    /**
     * Whether a shadow ray of its bundle's pyramid (ending at its apex), whose list {@link #lists}
     * made, meets anything listed with 0 &lt; t &lt; tMax; what it meets becomes {@link Ray#blocker},
     * which is -1 when nothing does.
     */
    boolean occluded(Ray ray, double tMax) {
        RayBundle b = ray.bundle;
        int[] ids = b.ids;
        for (int k = 0, count = b.count; k < count; k++) {
            int at = ids[k];
            if (at >= 0 ? bounded.any(at, at + 1, ray, tMax) : planes.any(~at, ~at + 1, ray, tMax)) {
                return true;
            }
        }
        ray.blocker = -1;
        return false;
    }

    /** The nearest hit of a unit-length ray inside its bundle's pyramid, whose list {@link #lists} made. */
    boolean intersect(Ray ray, double tMax, Hit hit) {
        RayBundle b = ray.bundle;
        hit.primitive = ShapeLeaves.NONE;
        int count = b.count;
        int[] ids = b.ids;
        double[] near = b.near;
        double cull = tMax;
        for (int k = 0; k < count && near[k] <= cull; k++) {
            int at = ids[k];
            cull = at >= 0 ? bounded.nearest(at, at + 1, ray, tMax, cull, hit)
                    : planes.nearest(~at, ~at + 1, ray, tMax, cull, hit);
        }
        return hit.primitive != ShapeLeaves.NONE;
    }

    /**
     * Lists into the bundle what its pyramid holds, a camera bundle's nearest first: a slot of the
     * tree as itself, a plane k as {@code ~k}, in a shadow bundle's list only where its pyramid is
     * not clear of it ({@link Frustum#clearOf}: shadows of what stands above a floor); count -1
     * when they do not fit, or a shadow bundle has no pyramid ({@link #aimShadows}). Camera lists
     * keep every plane: leaving out a floor above its horizon gained nothing measurable (whole
     * six-materials processes).
     */
    private void list(RayBundle b) {
        int[] ids = b.ids;
        Frustum pyramid = b.pyramid();
        b.count = -1;
        if (!b.fromApex() && !aimShadows(b)) {
            return;
        }
        double[] f = planeFrames;
        int listed = 0;
        for (int k = 0; k < planeIndex.length; k++) {
            int o = 6 * k;
            if (b.fromApex() || !pyramid.clearOf(f[o], f[o + 1], f[o + 2], f[o + 3], f[o + 4], f[o + 5])) {
                if (listed == ids.length) {
                    return;
                }
                ids[listed++] = ~k;
            }
        }
        int n = tree.slotsIn(pyramid.within(magnitude), slotBoxes, ids, listed, b.stack);
        b.count = n;
        if (n > 0 && b.fromApex()) {
            order(ids, n, b.apexX(), b.apexY(), b.apexZ(), b.near);
        }
    }

    /**
     * Sets a shadow bundle's pyramid: from its light over where its camera bundle's rays can hit
     * its object, the part of the object's box (or plane) inside their pyramid. False when there
     * is none: the object is not in this set, the plane's part is unbounded (a pixel on its
     * horizon), or the light lies inside or beside the part's box.
     */
    private boolean aimShadows(RayBundle b) {
        int object = b.object();
        int id = object >= 0 && object < idOfShape.length ? idOfShape[object] : NOT_HERE;
        if (id == NOT_HERE) {
            return false;
        }
        Frustum cameraRays = b.source().pyramid();
        double[] box = b.box, f = planeFrames;
        box[0] = box[1] = box[2] = Double.POSITIVE_INFINITY;
        box[3] = box[4] = box[5] = Double.NEGATIVE_INFINITY;
        if (id >= 0) {
            cameraRays.widenToPart(slotBoxes, 6 * id, box);
        } else {
            int o = 6 * ~id;
            if (!cameraRays.widenToPlane(f[o], f[o + 1], f[o + 2], f[o + 3], f[o + 4], f[o + 5], box)) {
                return false;
            }
        }
        return box[0] <= box[3] && box[1] <= box[4] && box[2] <= box[5]
                && b.pyramid().overBox(b.apexX(), b.apexY(), b.apexZ(), box);
    }

    /**
     * Orders the listed shapes by how near rays from (px, py, pz) could first hit them, nearest
     * first, ties by declaration (the order the linear loop would meet them in), and puts into
     * {@code near[k]} a bound below every unit-length ray's hit distance on entry k: its box's
     * distance from the point (a hit lies in the box, which is padded for the shape's rounding),
     * shrunk by {@link #NEAR_SHRINK}, and 0 for a plane. The distances first, then an insertion sort:
     * in one loop, C2's profiled loop predicates failed 4-5 times a process, each failure a recompile
     * of the bundle search (-Xlog:deoptimization; docs/cluster.md, "The warm job's compiles").
     */
    private void order(int[] ids, int count, double px, double py, double pz, double[] near) {
        for (int k = 0; k < count; k++) {
            int id = ids[k];
            near[k] = id >= 0 ? Aabb.distance(slotBoxes, 6 * id, px, py, pz) * NEAR_SHRINK : 0;
        }
        for (int k = 1; k < count; k++) {
            int id = ids[k];
            double d = near[k];
            int shape = shapeOf(id);
            int j = k - 1;
            while (j >= 0 && (near[j] > d || near[j] == d && shapeOf(ids[j]) > shape)) {
                near[j + 1] = near[j];
                ids[j + 1] = ids[j];
                j--;
            }
            near[j + 1] = d;
            ids[j + 1] = id;
        }
    }

    private int shapeOf(int id) {
        return id >= 0 ? slotShapes[id] : planeIndex[~id];
    }
}

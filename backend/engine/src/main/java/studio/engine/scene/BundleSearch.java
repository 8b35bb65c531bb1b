package studio.engine.scene;

import studio.engine.accel.Aabb;
import studio.engine.accel.PlaneLeaves;
import studio.engine.accel.ShapeLeaves;
import studio.engine.accel.Traversal;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.RayBundle;

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

    BundleSearch(Traversal tree, ShapeLeaves bounded, int[] slotShapes, double[] slotBoxes, PlaneLeaves planes,
                 int[] planeIndex, double magnitude) {
        this.tree = tree;
        this.bounded = bounded;
        this.slotShapes = slotShapes;
        this.slotBoxes = slotBoxes;
        this.planes = planes;
        this.planeIndex = planeIndex;
        this.magnitude = magnitude;
    }

    /** Whether the bundle holds a list for {@code owner} (made now if need be): false when its pyramid holds too many shapes. */
    boolean lists(RayBundle b, Object owner) {
        if (b.listedBy != owner) {
            list(b);
            b.listedBy = owner;
        }
        return b.count >= 0;
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
     * Lists into the bundle what its pyramid holds, nearest first: a slot of the tree as itself, a
     * plane k as {@code ~k}; count -1 when they do not fit.
     */
    private void list(RayBundle b) {
        int[] ids = b.ids;
        if (planeIndex.length > ids.length) {
            b.count = -1;
            return;
        }
        for (int k = 0; k < planeIndex.length; k++) {
            ids[k] = ~k;
        }
        int n = tree.slotsIn(b.pyramid().within(magnitude), slotBoxes, ids, planeIndex.length, b.stack);
        b.count = n;
        if (n > 0) {
            order(ids, n, b.apexX(), b.apexY(), b.apexZ(), b.near);
        }
    }

    /**
     * Orders the listed shapes by how near rays from (px, py, pz) could first hit them, nearest
     * first, ties by declaration (the order the linear loop would meet them in), and puts into
     * {@code near[k]} a bound below every unit-length ray's hit distance on entry k: its box's
     * distance from the point (a hit lies in the box, which is padded for the shape's rounding),
     * shrunk by {@link #NEAR_SHRINK}, and 0 for a plane.
     */
    private void order(int[] ids, int count, double px, double py, double pz, double[] near) {
        for (int k = 0; k < count; k++) {
            int id = ids[k];
            double d = id >= 0 ? Aabb.distance(slotBoxes, 6 * id, px, py, pz) * NEAR_SHRINK : 0;
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

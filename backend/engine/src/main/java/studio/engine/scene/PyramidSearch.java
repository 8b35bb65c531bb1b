package studio.engine.scene;

import studio.engine.accel.Aabb;
import studio.engine.accel.Traversal;
import studio.engine.geometry.Frustum;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Shape;

/**
 * {@link ShapeSet#nothingIn}: whether no shape of a set but one may lie in a pyramid, which
 * proves that nothing stops a segment inside it. Conservative: a shape whose box merely comes near
 * the pyramid counts as in it ({@link Frustum#mayMeet}), a plane counts unless the pyramid is
 * clearly on one side of it ({@link Frustum#clearOf}), and a shape with no box always counts. The
 * tree's walk stops at the first shape found.
 */
final class PyramidSearch {

    /** The set's tree over its bounded shapes (null: none), their boxes per slot, and each slot's shape. */
    private final Traversal tree;
    private final double[] slotBoxes;
    /** Per shape (by index), its slot in the tree, or -1. */
    private final int[] slotOfShape;
    /** Shapes outside the tree: their boxes (NaN: none, so always counted), and their indices. */
    private final double[] boxes;
    private final int[] boxShapes;
    private final Plane[] planes;
    private final int[] planeShapes;
    /** The largest magnitude of any box's coordinates ({@link Frustum#within}). */
    private final double magnitude;

    /**
     * Over {@code tree} (null: none) with its slots' boxes and each shape's slot, the largest
     * magnitude of the tree's coordinates (its root box's), and the shapes {@code outside} (indices
     * into {@code shapes}) tested one by one.
     */
    PyramidSearch(Shape[] shapes, Traversal tree, double[] slotBoxes, int[] slotOfShape, double treeMagnitude,
                  int[] outside) {
        this.tree = tree;
        this.slotBoxes = slotBoxes;
        this.slotOfShape = slotOfShape;
        int planeCount = 0;
        for (int index : outside) {
            planeCount += shapes[index] instanceof Plane ? 1 : 0;
        }
        planes = new Plane[planeCount];
        planeShapes = new int[planeCount];
        boxes = new double[6 * (outside.length - planeCount)];
        boxShapes = new int[outside.length - planeCount];
        double largest = treeMagnitude;
        for (int k = 0, p = 0, b = 0; k < outside.length; k++) {
            Shape shape = shapes[outside[k]];
            if (shape instanceof Plane plane) {
                planes[p] = plane;
                planeShapes[p++] = outside[k];
                continue;
            }
            Aabb box = shape.bounds();
            double[] corners = {box.minX(), box.minY(), box.minZ(), box.maxX(), box.maxY(), box.maxZ()};
            for (int c = 0; c < 6; c++) {
                boolean finite = box.isBounded() && Double.isFinite(corners[c]);
                boxes[6 * b + c] = finite ? corners[c] : Double.NaN;
                largest = finite ? Math.max(largest, Math.abs(corners[c])) : largest;
            }
            boxShapes[b++] = outside[k];
        }
        this.magnitude = largest;
    }

    /**
     * Whether no shape but shape {@code except} (-1: none) may lie in the pyramid, which ends;
     * {@code reach} (six doubles) and {@code stack} are the caller's scratch.
     */
    boolean nothingIn(Frustum pyramid, int except, double[] reach, int[] stack) {
        pyramid.within(magnitude);
        for (int k = 0; k < planes.length; k++) {
            if (planeShapes[k] != except && !pyramid.clearOf(planes[k].point().x(), planes[k].point().y(),
                    planes[k].point().z(), planes[k].normal().x(), planes[k].normal().y(), planes[k].normal().z())) {
                return false;
            }
        }
        for (int k = 0; k < boxShapes.length; k++) {
            if (boxShapes[k] != except && pyramid.mayMeet(boxes, 6 * k)) {
                return false;
            }
        }
        if (tree == null) {
            return true;
        }
        int exceptSlot = except >= 0 && except < slotOfShape.length ? slotOfShape[except] : -1;
        pyramid.bounds(reach);
        return !tree.anyIn(pyramid, reach, slotBoxes, exceptSlot, stack);
    }
}

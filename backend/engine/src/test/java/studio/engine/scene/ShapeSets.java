package studio.engine.scene;

import java.util.List;

import studio.engine.geometry.Shape;

/** Shape sets that always take one way, whatever their size: the references of tests and timings. */
final class ShapeSets {

    private ShapeSets() {
    }

    /** Always the linear loop. */
    static ShapeSet linear(Shape... shapes) {
        return new ShapeSet(shapes, false, List.of());
    }

    /** Always a BVH over the bounded shapes, if there are any. */
    static ShapeSet bvh(Shape... shapes) {
        return new ShapeSet(shapes, true, List.of());
    }
}

package studio.engine.scene;

import java.util.ArrayList;
import java.util.List;

import studio.engine.accel.Aabb;
import studio.engine.geometry.Shape;

/**
 * Where an edit from one scene to the next can change a render: nowhere, in the boxes of the
 * objects the edit changed (each before and after), or anywhere. Which objects changed is told by
 * whoever made the edit (the live view knows it from the edit's paths), not worked out again here.
 * A different camera, light, background, ambient term or number of objects, a changed unbounded
 * object (a plane), or more than {@value #MAX_CHANGED} changed objects, may reach every pixel.
 */
public final class SceneEdit {

    /** More changed objects than this count as a change anywhere: forgetting pixel by pixel would cost more than rendering. */
    public static final int MAX_CHANGED = 64;

    private SceneEdit() {
    }

    /**
     * The boxes of the objects the edit changed, each object's box in {@code before} and in
     * {@code after} (empty if nothing changed); null if the edit may change any pixel.
     *
     * @param origins for each object of {@code after}, the index of the object of {@code before} it
     *                is unchanged from (shape and material), or -1; null when that is not known
     */
    public static List<Aabb> changedBoxes(Scene before, Scene after, int[] origins) {
        List<Shape> shapes = changedShapes(before, after, origins);
        return shapes == null ? null : shapes.stream().map(Shape::bounds).toList();
    }

    /**
     * The shapes of the objects the edit changed, each object's in {@code before} and in
     * {@code after} (empty if nothing changed), every one bounded; null if the edit may change any
     * pixel. As {@link #changedBoxes}.
     */
    public static List<Shape> changedShapes(Scene before, Scene after, int[] origins) {
        if (origins == null || origins.length != after.objectCount() || !before.camera().equals(after.camera())
                || !before.lights().equals(after.lights()) || !before.background().equals(after.background())
                || Double.compare(before.ambient(), after.ambient()) != 0
                || before.objectCount() != after.objectCount()) {
            return null;
        }
        List<Shape> shapes = new ArrayList<>();
        for (int i = 0; i < after.objectCount(); i++) {
            if (origins[i] == i) {
                continue;
            }
            if (shapes.size() == 2 * MAX_CHANGED) {
                return null;
            }
            Shape was = before.shape(i), is = after.shape(i);
            if (!was.bounds().isBounded() || !is.bounds().isBounded()) {
                return null;
            }
            shapes.add(was);
            shapes.add(is);
        }
        return shapes;
    }
}

package studio.engine.scene;

import java.util.ArrayList;
import java.util.List;

import studio.engine.accel.Aabb;
import studio.engine.geometry.Shape;

/**
 * Where an edit from one scene to the next can change a render: nowhere, in the boxes of the
 * objects that differ (each before and after), or anywhere. Objects are matched by their place in
 * the list; an object is the same if its shape and material are equal (shapes and materials are
 * values, a mesh is the same instance). A different camera, light, background, ambient term or
 * number of objects, or a changed unbounded object (a plane), may reach every pixel.
 */
public final class SceneEdit {

    private SceneEdit() {
    }

    /**
     * The boxes of the objects that differ between the scenes, each object's box in {@code before}
     * and in {@code after} (empty if nothing differs); null if the edit may change any pixel.
     */
    public static List<Aabb> changedBoxes(Scene before, Scene after) {
        if (!before.camera().equals(after.camera()) || !before.lights().equals(after.lights())
                || !before.background().equals(after.background())
                || Double.compare(before.ambient(), after.ambient()) != 0
                || before.objectCount() != after.objectCount()) {
            return null;
        }
        List<Aabb> boxes = new ArrayList<>();
        for (int i = 0; i < before.objectCount(); i++) {
            Shape was = before.shape(i), is = after.shape(i);
            if ((was == is || was.equals(is)) && before.material(i).equals(after.material(i))) {
                continue;
            }
            Aabb wasBox = was.bounds(), isBox = is.bounds();
            if (!wasBox.isBounded() || !isBox.isBounded()) {
                return null;
            }
            boxes.add(wasBox);
            boxes.add(isBox);
        }
        return boxes;
    }
}

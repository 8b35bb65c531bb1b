package studio.engine.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Sphere;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;

class SceneValidationTest {

    private static final Camera CAMERA = new Camera(new Vec3(0, 0, 5), Vec3.ZERO, new Vec3(0, 1, 0), 45);
    private static final List<SceneObject> OBJECTS = List.of(
            new SceneObject(new Sphere(Vec3.ZERO, 1), MaterialDefaults.of(MaterialKind.CHALK, null)));

    @Test
    void sceneKeepsObjectsInDeclarationOrder() {
        SceneObject second = new SceneObject(new Sphere(new Vec3(3, 0, 0), 1),
                MaterialDefaults.of(MaterialKind.MIRROR, null));
        Scene scene = new Scene(CAMERA, List.of(OBJECTS.get(0), second), List.of(), Rgb.BLACK, 0.1);

        assertEquals(2, scene.objectCount());
        assertEquals(OBJECTS.get(0).shape(), scene.shape(0));
        assertEquals(second.material(), scene.material(1));
    }

    @Test
    void sceneRejectsMissingPartsAndInvalidAmbient() {
        assertThrows(IllegalArgumentException.class, () -> new Scene(null, OBJECTS, List.of(), Rgb.BLACK, 0.1));
        assertThrows(IllegalArgumentException.class, () -> new Scene(CAMERA, OBJECTS, List.of(), null, 0.1));
        assertThrows(IllegalArgumentException.class, () -> new Scene(CAMERA, OBJECTS, List.of(), Rgb.BLACK, -0.1));
        assertThrows(IllegalArgumentException.class,
                () -> new Scene(CAMERA, OBJECTS, List.of(), Rgb.BLACK, Double.NaN));
    }

    @Test
    void sceneRejectsNegativeOrNonFiniteBackgroundBeforeRendering() {
        // A NaN background would reach the film as NaN and be stored as black.
        assertThrows(IllegalArgumentException.class,
                () -> new Scene(CAMERA, OBJECTS, List.of(), new Rgb(Double.NaN, 0, 0), 0.1));
        assertThrows(IllegalArgumentException.class,
                () -> new Scene(CAMERA, OBJECTS, List.of(), new Rgb(0, Double.POSITIVE_INFINITY, 0), 0.1));
        assertThrows(IllegalArgumentException.class,
                () -> new Scene(CAMERA, OBJECTS, List.of(), new Rgb(0, 0, -1), 0.1));
    }
}

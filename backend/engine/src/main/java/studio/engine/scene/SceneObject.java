package studio.engine.scene;

import studio.engine.geometry.Shape;
import studio.engine.material.Material;

/** A shape with its material. */
public record SceneObject(Shape shape, Material material) {

    public SceneObject {
        if (shape == null || material == null) {
            throw new IllegalArgumentException("a scene object needs a shape and a material");
        }
    }
}

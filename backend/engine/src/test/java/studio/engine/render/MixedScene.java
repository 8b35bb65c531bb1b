package studio.engine.render;

import java.util.List;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Sphere;
import studio.engine.light.PointLight;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/**
 * The render tests' scene of every kind of path: a chalk floor, a glass sphere and a mirror sphere
 * facing each other, a rotated plastic box with edges, and two lights, one with fall-off.
 */
final class MixedScene {

    static final Scene SCENE = new Scene(
            new Camera(new Vec3(0, 2, 6), new Vec3(0, 0.5, 0), new Vec3(0, 1, 0), 50),
            List.of(new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)),
                            MaterialDefaults.of(MaterialKind.CHALK, new Rgb(0.7, 0.7, 0.7))),
                    new SceneObject(new Sphere(new Vec3(-1.2, 1, 0), 1), MaterialDefaults.of(MaterialKind.GLASS, null)),
                    new SceneObject(new Sphere(new Vec3(1.2, 1, -0.5), 1),
                            MaterialDefaults.of(MaterialKind.MIRROR, null)),
                    new SceneObject(new Box(new Vec3(0, 0.5, -2), new Vec3(1, 1, 1), new Vec3(0, 30, 0)),
                            MaterialDefaults.of(MaterialKind.PLASTIC, new Rgb(0.8, 0.2, 0.1)))),
            List.of(new PointLight(new Vec3(3, 6, 2), Rgb.WHITE, 1, false),
                    new PointLight(new Vec3(-4, 3, 4), new Rgb(0.3, 0.4, 1), 30, true)),
            new Rgb(0.2, 0.3, 0.5), 0.1);

    private MixedScene() {
    }
}

package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Sphere;
import studio.engine.light.PointLight;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.sampler.Sampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/**
 * Shadows without glass, where a shadow ray only asks whether anything blocks it, come out bit
 * for bit as recorded: 60 small spheres and boxes over a floor, shadowing each other and the floor
 * from three lights, one inside the cloud. The fingerprint was recorded before each thread kept
 * the last object that blocked a light and tried it first (the shadow cache): the cache may only
 * save work, never change a pixel. Recorded again when a light too faint to show stopped being
 * looked for ({@link Integrator#NEGLIGIBLE_LIGHT}), which changes values by less than a millionth.
 */
class OpaqueShadowsUnchangedTest {

    static Scene scene() {
        Random random = new Random(7);
        List<SceneObject> objects = new ArrayList<>();
        objects.add(new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)),
                MaterialDefaults.of(MaterialKind.CHALK, new Rgb(0.7, 0.7, 0.7))));
        MaterialKind[] kinds = {MaterialKind.CHALK, MaterialKind.PLASTIC, MaterialKind.METAL, MaterialKind.MIRROR};
        for (int i = 0; i < 60; i++) {
            Vec3 at = new Vec3(random.nextDouble() * 4 - 2, 0.2 + random.nextDouble() * 2, random.nextDouble() * 3 - 2);
            Rgb color = new Rgb(random.nextDouble(), random.nextDouble(), random.nextDouble());
            var material = MaterialDefaults.of(kinds[i % kinds.length], color);
            objects.add(new SceneObject(i % 3 == 0
                    ? new Box(at, new Vec3(0.3, 0.3, 0.3), new Vec3(0, 20 * i, 10))
                    : new Sphere(at, 0.1 + 0.15 * random.nextDouble()), material));
        }
        return new Scene(new Camera(new Vec3(0, 2.5, 5), new Vec3(0, 0.8, -0.5), new Vec3(0, 1, 0), 50), objects,
                List.of(new PointLight(new Vec3(3, 6, 2), Rgb.WHITE, 1, false),
                        new PointLight(new Vec3(-4, 3, 4), new Rgb(0.3, 0.4, 1), 30, true),
                        new PointLight(new Vec3(0, 1.2, -0.5), new Rgb(1, 0.8, 0.5), 2, true)),
                new Rgb(0.2, 0.3, 0.5), 0.1);
    }

    @Test
    void shadowsOfOpaqueObjectsAreAsRecorded() {
        RenderSettings settings = new RenderSettings(64, 48, Sampler.of("jittered", 4), 4, 2, 42L,
                RenderSettings.DEFAULT_MIN_PATH_WEIGHT, 0);

        RenderResult result = Renderer.render(RenderRequest.of(scene(), settings));

        assertEquals("58181f3cfee8cf6e", SampledImagesUnchangedTest.fingerprint(result.film()));
    }
}

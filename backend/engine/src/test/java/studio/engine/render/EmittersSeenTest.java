package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Sphere;
import studio.engine.light.AreaLight;
import studio.engine.light.SphereLight;
import studio.engine.material.Material;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/** Camera and specular rays see sphere and area lights as colour times intensity. */
class EmittersSeenTest {

    @Test
    void aMirrorShowsASphereLightTimesItsTintAndReflectivity() {
        Material mirror = MaterialDefaults.of(MaterialKind.MIRROR, new Rgb(0.9, 0.8, 0.7));
        Scene scene = new Scene(new Camera(new Vec3(0, 1, 5), Vec3.ZERO, new Vec3(0, 1, 0), 40),
                List.of(new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)), mirror)),
                List.of(new SphereLight(new Vec3(0, 2, -6), 0.5, new Rgb(1, 0.5, 0.25), 3, true)), Rgb.BLACK, 0);
        Integrator integrator = new Integrator(scene, 4, RenderSettings.DEFAULT_MIN_PATH_WEIGHT);

        // from (0, 1, 0) down to the mirror at (0, 0, -2), reflected up through the light's centre (0, 2, -6)
        Rgb seen = Radiance.of(integrator, new Ray(0, 1, 0, 0, -1, -2));

        double k = mirror.reflectivity();
        assertEquals(0.9 * k * 3, seen.r(), 1e-12);
        assertEquals(0.8 * k * 1.5, seen.g(), 1e-12);
        assertEquals(0.7 * k * 0.75, seen.b(), 1e-12);
    }

    @Test
    void theCameraSeesAnAreaLightsFrontAndNotItsBack() {
        Scene scene = new Scene(new Camera(new Vec3(0, 1, 5), Vec3.ZERO, new Vec3(0, 1, 0), 40),
                List.of(new SceneObject(new Sphere(new Vec3(0, 0, -10), 1), MaterialDefaults.of(MaterialKind.FLAT,
                        new Rgb(0.2, 0.2, 0.2)))),
                List.of(new AreaLight(Vec3.ZERO, 2, 2, new Vec3(0, 0, 5), new Rgb(1, 1, 0.5), 2, false, false)),
                new Rgb(0.1, 0.1, 0.1), 0);
        Integrator integrator = new Integrator(scene, 2, RenderSettings.DEFAULT_MIN_PATH_WEIGHT);

        assertEquals(new Rgb(2, 2, 1), Radiance.of(integrator, new Ray(0.5, 0.5, 5, 0, 0, -1)), "its front");
        assertEquals(new Rgb(0.2, 0.2, 0.2), Radiance.of(integrator, new Ray(0, 0, -5, 0, 0, -1)), "from behind: what is beyond");
    }
}

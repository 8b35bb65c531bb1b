package studio.engine.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.light.PointLight;
import studio.engine.material.Material;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.mesh.MeshShapes;
import studio.engine.render.Film;
import studio.engine.render.RenderResult;
import studio.engine.render.RenderSettings;
import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.engine.sampler.RegularSampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/**
 * A smooth-shaded icosphere on a floor, lit and shadowed, renders like the analytic sphere it
 * approximates: no NaN, and per-pixel differences only along the polygonal silhouette. Rendered
 * among enough other objects that the scene's BVH is used.
 */
class MeshRenderTest {

    private static final int SIZE = 96;
    private static final Camera CAMERA = new Camera(new Vec3(0, 2, 5), new Vec3(0, 1, 0), new Vec3(0, 1, 0), 40);
    private static final Material PLASTIC = MaterialDefaults.of(MaterialKind.PLASTIC, new Rgb(0.8, 0.3, 0.2));
    private static final Material CHALK = MaterialDefaults.of(MaterialKind.CHALK, null);

    @Test
    void smoothIcosphereRendersLikeTheSphereItApproximates() {
        Film mesh = render(new TriangleMesh(MeshShapes.icosphere(5), new Vec3(0, 1, 0), 1, new Vec3(0, 30, 0)));
        Film sphere = render(new Sphere(new Vec3(0, 1, 0), 1));

        double sum = 0;
        int far = 0;
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                for (int c = 0; c < 3; c++) {
                    double d = Math.abs(mesh.get(x, y, c) - sphere.get(x, y, c));
                    sum += d;
                    far += d > 0.05 ? 1 : 0;
                }
            }
        }
        double mean = sum / (3.0 * SIZE * SIZE);
        assertTrue(mean < 1e-4, "mean absolute difference " + mean); // measured 1.0e-5
        assertTrue(far < 0.002 * 3 * SIZE * SIZE, "channels off by more than 0.05: " + far); // measured 0
    }

    private static Film render(Shape shape) {
        List<SceneObject> objects = new ArrayList<>();
        objects.add(new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)), CHALK));
        objects.add(new SceneObject(shape, PLASTIC));
        for (int i = 0; i < 8; i++) { // out of view, so only the BVH changes
            objects.add(new SceneObject(new Sphere(new Vec3(-20 + 5 * i, 0.5, 20), 0.5), CHALK));
        }
        Scene scene = new Scene(CAMERA, objects, List.of(new PointLight(new Vec3(3, 6, 4), Rgb.WHITE, 1, false)),
                new Rgb(0.1, 0.1, 0.15), 0.1);
        RenderResult result = Renderer.render(RenderRequest.of(scene, new RenderSettings(SIZE, SIZE, new RegularSampler(1), 3, 1)));
        assertEquals(0, result.nonFiniteSamples());
        return result.film();
    }
}

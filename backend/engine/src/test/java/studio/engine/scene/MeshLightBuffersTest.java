package studio.engine.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Sphere;
import studio.engine.geometry.TriangleMesh;
import studio.engine.light.PointLight;
import studio.engine.material.Material;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.memory.CountingGate;
import studio.engine.memory.MemoryGate;
import studio.engine.mesh.MeshShapes;
import studio.engine.render.Film;
import studio.engine.render.RenderSettings;
import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.engine.sampler.JitteredSampler;

/** Meshes get light buffers only where a render pays for them, and render the same pixels with them. */
class MeshLightBuffersTest {

    private static final Material PLASTIC = MaterialDefaults.of(MaterialKind.PLASTIC, new Rgb(0.9, 0.6, 0.2));
    private static final Material GLASS = MaterialDefaults.of(MaterialKind.GLASS, null);
    private static final Material CHALK = MaterialDefaults.of(MaterialKind.CHALK, null);
    private static final List<PointLight> LIGHTS = List.of(new PointLight(new Vec3(-3, 6, 4), Rgb.WHITE, 0.8, false),
            new PointLight(new Vec3(5, 4, -2), new Rgb(1, 0.85, 0.66), 0.35, false),
            new PointLight(new Vec3(0, 1.5, 0.2), Rgb.WHITE, 0.2, false)); // inside the knot's box: no buffer

    private static List<SceneObject> objects() {
        TriangleMesh knot = new TriangleMesh(MeshShapes.torusKnot(2, 3, 200, 16), new Vec3(0, 1.6, 0), 0.8,
                new Vec3(-20, 25, 15)); // 6,400 triangles
        return List.of(new SceneObject(knot, PLASTIC), new SceneObject(new Sphere(new Vec3(1.8, 0.5, 1.2), 0.5), GLASS),
                new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)), CHALK));
    }

    @Test
    void aMeshGetsBuffersOnlyWhenTheRenderHasEightCameraSamplesForEachOfItsTriangles() {
        List<SceneObject> objects = objects();
        assertSame(objects, MeshLightBuffers.forRender(objects, LIGHTS, 8 * 6_400 - 1, MemoryGate.UNLIMITED));
        assertSame(objects, MeshLightBuffers.forRender(objects, List.of(), 1 << 30, MemoryGate.UNLIMITED));
        CountingGate gate = new CountingGate(), two = new CountingGate();
        List<SceneObject> lit = MeshLightBuffers.forRender(objects, LIGHTS, 8 * 6_400, gate);
        ((TriangleMesh) objects.get(0).shape()).withLightBuffers(
                List.of(LIGHTS.get(0).position(), LIGHTS.get(1).position()), two);
        assertTrue(two.granted() > 0);
        assertEquals(two.granted(), gate.granted(), "the buffers of the first two lights: the third is inside the box");
        assertSame(objects.get(0).material(), lit.get(0).material());
        assertSame(objects.get(1), lit.get(1));
        assertSame(objects.get(2), lit.get(2));
    }

    @Test
    void aSceneRendersTheSamePixelsWithAndWithoutLightBuffers() {
        Camera camera = new Camera(new Vec3(0, 3.2, 7.5), new Vec3(0, 1.4, 0), new Vec3(0, 1, 0), 40);
        RenderSettings settings = new RenderSettings(160, 120, new JitteredSampler(4), 6, 2);
        Film plain = Renderer.render(RenderRequest.of(new Scene(camera, objects(), LIGHTS, new Rgb(0.1, 0.1, 0.12), 0.07), settings)).film();
        CountingGate gate = new CountingGate();
        List<SceneObject> lit = MeshLightBuffers.forRender(objects(), LIGHTS, settings.cameraSamples(), gate);
        assertTrue(gate.granted() > 0, "the mesh's buffers were made");
        Film buffered = Renderer.render(RenderRequest.of(new Scene(camera, lit, LIGHTS, new Rgb(0.1, 0.1, 0.12), 0.07), settings)).film();
        int differing = 0;
        for (int y = 0; y < 120; y++) {
            for (int x = 0; x < 160; x++) {
                for (int c = 0; c < 3; c++) {
                    differing += plain.get(x, y, c) == buffered.get(x, y, c) ? 0 : 1;
                }
            }
        }
        assertEquals(0, differing, "channels that differ");
    }
}

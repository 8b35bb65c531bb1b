package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Sphere;
import studio.engine.light.AreaLight;
import studio.engine.light.Light;
import studio.engine.light.PointLight;
import studio.engine.light.SphereLight;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;
import studio.engine.geometry.TriangleMesh;
import studio.engine.material.Material;
import studio.engine.mesh.MeshShapes;
import studio.engine.memory.MemoryGate;
import studio.engine.texture.CheckerTexture;
import studio.engine.texture.ImageTexture;
import studio.engine.texture.MipMap;
import studio.engine.texture.Texture;

/**
 * Allocation guard for the whole hot loop: camera ray, intersection, shading with shadow rays through
 * glass, mirror and glass recursion, under point lights and under sphere and area lights. 10^5
 * camera samples after warm-up allocate (almost) nothing:
 * rays, hits and radiance live in per-thread, per-depth slots. (Before this guard, each sample
 * allocated a ray per bounce and shadow ray and a colour per shading step.)
 */
class TraceAllocationTest {

    /** JDK 17's incubating Vector API allocates in the box test (some 720 bytes a ray); the automatic choice never takes it there. */
    @BeforeAll
    static void notJdk17sVectorPath() {
        Assumptions.assumeTrue(!studio.engine.accel.WideBoxTests.vectorized() || Runtime.version().feature() >= 20,
                "the Vector API allocates before JDK 20");
    }


    private static final int SAMPLES = 100_000;
    /** Slack for the measuring itself. */
    private static final long MAX_BYTES = 4096;

    /** Every material, glass and mirror facing each other, two lights (one with fall-off), 40 objects (a BVH). */
    private static Scene scene() {
        return scene(List.of(new PointLight(new Vec3(3, 6, 2), Rgb.WHITE, 1, false),
                new PointLight(new Vec3(-4, 3, 4), new Rgb(0.3, 0.4, 1), 30, true)));
    }

    private static Scene scene(List<Light> lights) {
        Random random = new Random(3);
        List<SceneObject> objects = new ArrayList<>();
        objects.add(new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)),
                MaterialDefaults.of(MaterialKind.CHALK, new Rgb(0.7, 0.7, 0.7))));
        MaterialKind[] kinds = MaterialKind.values();
        for (int i = 0; i < 40; i++) {
            Vec3 c = new Vec3(random.nextDouble() * 8 - 4, random.nextDouble() * 2 + 0.3, random.nextDouble() * 8 - 4);
            MaterialKind kind = kinds[i % kinds.length];
            objects.add(new SceneObject(i % 2 == 0 ? new Sphere(c, 0.3 + random.nextDouble() * 0.4)
                    : new Box(c, new Vec3(0.6, 0.5, 0.4), new Vec3(10 * i, 20, 5)),
                    MaterialDefaults.of(kind, new Rgb(0.9, 0.6, 0.3))));
        }
        return new Scene(new Camera(new Vec3(0, 3, 9), new Vec3(0, 1, 0), new Vec3(0, 1, 0), 50), objects,
                lights, new Rgb(0.2, 0.3, 0.5), 0.1);
    }

    /**
     * The same kind of scene with every material textured, half by checks and half by an image, on
     * every shape (a mesh among them): texture coordinates, footprints and filtered lookups at every
     * depth, through mirrors and glass.
     */
    private static Scene texturedScene() {
        Random random = new Random(4);
        int[] pixels = new int[64 * 32];
        for (int i = 0; i < pixels.length; i++) {
            pixels[i] = random.nextInt(1 << 24);
        }
        Texture image = new ImageTexture(MipMap.fromSrgb(64, 32, pixels, MemoryGate.UNLIMITED), 2, 3);
        Texture checks = new CheckerTexture(new Rgb(0.1, 0.2, 0.3), new Rgb(0.9, 0.8, 0.7), 0.25);
        List<SceneObject> objects = new ArrayList<>();
        objects.add(new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)),
                MaterialDefaults.of(MaterialKind.CHALK, new Rgb(0.7, 0.7, 0.7)).withTexture(checks)));
        objects.add(new SceneObject(new TriangleMesh(MeshShapes.icosphere(2), new Vec3(0, 1, -2), 1, Vec3.ZERO),
                MaterialDefaults.of(MaterialKind.PLASTIC, Rgb.WHITE).withTexture(image)));
        MaterialKind[] kinds = MaterialKind.values();
        for (int i = 0; i < 40; i++) {
            Vec3 c = new Vec3(random.nextDouble() * 8 - 4, random.nextDouble() * 2 + 0.3, random.nextDouble() * 8 - 4);
            Material m = MaterialDefaults.of(kinds[i % kinds.length], new Rgb(0.9, 0.6, 0.3))
                    .withTexture(i % 4 < 2 ? checks : image);
            objects.add(new SceneObject(i % 2 == 0 ? new Sphere(c, 0.3 + random.nextDouble() * 0.4)
                    : new Box(c, new Vec3(0.6, 0.5, 0.4), new Vec3(10 * i, 20, 5)), m));
        }
        return new Scene(new Camera(new Vec3(0, 3, 9), new Vec3(0, 1, 0), new Vec3(0, 1, 0), 50), objects,
                List.of(new PointLight(new Vec3(3, 6, 2), Rgb.WHITE, 1, false),
                        new PointLight(new Vec3(-4, 3, 4), new Rgb(0.3, 0.4, 1), 30, true)),
                new Rgb(0.2, 0.3, 0.5), 0.1);
    }

    @Test
    void tracingCameraSamplesAllocatesNothing() {
        assertTracingAllocatesNothing(scene());
    }

    /** Sphere and area lights: sampling them, their shadow rays and the emitters camera and mirror rays see. */
    @Test
    void tracingUnderSoftLightsAllocatesNothing() {
        assertTracingAllocatesNothing(scene(List.of(new SphereLight(new Vec3(3, 6, 2), 0.8, Rgb.WHITE, 1, false),
                new AreaLight(new Vec3(-4, 3, 4), 2, 1, Vec3.ZERO, new Rgb(0.3, 0.4, 1), 30, true, false),
                new PointLight(new Vec3(0, 5, -3), Rgb.WHITE, 0.3, false))));
    }

    @Test
    void tracingTexturedSurfacesAllocatesNothing() {
        assertTracingAllocatesNothing(texturedScene());
    }

    private static void assertTracingAllocatesNothing(Scene scene) {
        Integrator integrator = new Integrator(scene, 8, RenderSettings.DEFAULT_MIN_PATH_WEIGHT);
        integrator.coneSpread = 1e-3;
        Ray ray = new Ray();
        double[] sink = new double[1];
        Random random = new Random(5);
        double[] xs = new double[SAMPLES], ys = new double[SAMPLES];
        for (int i = 0; i < SAMPLES; i++) {
            xs[i] = random.nextDouble() * 2 - 1;
            ys[i] = random.nextDouble() * 2 - 1;
        }
        traceAll(scene, integrator, ray, xs, ys, sink); // warm-up: lets the JIT compile the loop
        traceAll(scene, integrator, ray, xs, ys, sink);

        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long thread = Thread.currentThread().getId();
        long before = threads.getThreadAllocatedBytes(thread);
        long rays = integrator.rays;
        traceAll(scene, integrator, ray, xs, ys, sink);
        long bytes = threads.getThreadAllocatedBytes(thread) - before;
        rays = integrator.rays - rays;

        assertTrue(rays > 2L * SAMPLES, "the scene should make secondary and shadow rays: " + rays);
        assertTrue(bytes < MAX_BYTES, "allocated " + bytes + " bytes for " + SAMPLES + " samples (" + rays + " rays)");
        assertTrue(Double.isFinite(sink[0]));
    }

    private static void traceAll(Scene scene, Integrator integrator, Ray ray, double[] xs, double[] ys, double[] sink) {
        double sum = 0;
        for (int i = 0; i < xs.length; i++) {
            integrator.lightU = (xs[i] + 1) / 2;
            integrator.lightV = (ys[i] + 1) / 2;
            integrator.trace(scene.camera().ray(xs[i], ys[i], 4.0 / 3, ray), 0, 1.0);
            sum += integrator.r() + integrator.g() + integrator.b();
        }
        sink[0] += sum;
    }
}

package studio.engine.scene;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Sphere;
import studio.engine.geometry.TriangleMesh;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.mesh.MeshShapes;

/**
 * Allocation guard: closest-hit and any-hit queries through the scene's BVH and a mesh's BVH
 * allocate nothing (the traversal stacks live in the reused {@link Hit}). Measured with the JVM's
 * per-thread allocation counter over 10^5 calls of each, after warm-up, rays made beforehand.
 */
class IntersectionAllocationTest {

    /** JDK 17's incubating Vector API allocates in the box test (some 720 bytes a ray); the automatic choice never takes it there. */
    @BeforeAll
    static void notJdk17sVectorPath() {
        Assumptions.assumeTrue(!studio.engine.accel.WideBoxTests.vectorized() || Runtime.version().feature() >= 20,
                "the Vector API allocates before JDK 20");
    }


    private static final int CALLS = 100_000;
    private static final long MAX_BYTES = 1024;
    private static final Camera CAMERA = new Camera(new Vec3(0, 0, 30), Vec3.ZERO, new Vec3(0, 1, 0), 45);

    @Test
    void thousandSpheresThroughTheSceneBvhAllocateNothing() {
        Random random = new Random(14);
        List<SceneObject> objects = new ArrayList<>();
        for (int i = 0; i < 1000; i++) {
            Vec3 c = new Vec3(random.nextDouble() * 20 - 10, random.nextDouble() * 20 - 10, random.nextDouble() * 20 - 10);
            objects.add(new SceneObject(new Sphere(c, 0.2 + random.nextDouble()), MaterialDefaults.of(MaterialKind.CHALK, null)));
        }
        long bytes = allocatedPerQueries(scene(objects));

        assertTrue(bytes < MAX_BYTES, "allocated " + bytes + " bytes over " + CALLS + " intersect and occluded calls");
    }

    @Test
    void tenThousandTriangleMeshAllocatesNothing() {
        TriangleMesh knot = new TriangleMesh(MeshShapes.torusKnot(2, 3, 200, 25), Vec3.ZERO, 6, new Vec3(20, 0, 0));
        long bytes = allocatedPerQueries(scene(List.of(
                new SceneObject(knot, MaterialDefaults.of(MaterialKind.CHALK, null)))));

        assertTrue(bytes < MAX_BYTES, "allocated " + bytes + " bytes over " + CALLS + " intersect and occluded calls");
    }

    private static Scene scene(List<SceneObject> objects) {
        return new Scene(CAMERA, objects, List.of(), Rgb.BLACK, 0.1);
    }

    private static long allocatedPerQueries(Scene scene) {
        Random random = new Random(15);
        Ray[] rays = new Ray[1024];
        for (int i = 0; i < rays.length; i++) {
            rays[i] = CAMERA.ray(random.nextDouble() * 2 - 1, random.nextDouble() * 2 - 1, 1.0);
        }
        Hit hit = new Hit();
        long sink = run(scene, rays, hit, CALLS); // warm-up: compiled before measuring
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long thread = Thread.currentThread().getId();
        long before = threads.getThreadAllocatedBytes(thread);
        sink += run(scene, rays, hit, CALLS);
        long after = threads.getThreadAllocatedBytes(thread);
        assertTrue(sink > 0, "some rays hit");
        return after - before;
    }

    private static long run(Scene scene, Ray[] rays, Hit hit, int calls) {
        long found = 0;
        for (int i = 0; i < calls; i++) {
            Ray ray = rays[i & (rays.length - 1)];
            if (scene.intersect(ray, Double.POSITIVE_INFINITY, hit)) {
                found++;
            }
            if (scene.occluded(ray, 40)) {
                found++;
            }
        }
        return found;
    }
}

package studio.engine.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Shape;
import studio.engine.geometry.Sphere;
import studio.engine.math.Vec3;

/**
 * The traversal as the engine makes it finds the nearest and any hit through the tree, large or
 * small, with the scratch this JVM's hits and rays carry (none where its walks stay binary).
 * Which walk a tree of a given size takes here is a speed choice, timed by
 * {@code studio-bench.jar kernel} and {@code wide}.
 */
class TraversalWideTest {

    @Test
    void findsHitsThroughLargeAndSmallTreesWithTheScratchOfThisJvm() {
        int n = 40;
        Shape[] spheres = new Shape[n];
        double[] boxes = new double[6 * n];
        for (int i = 0; i < n; i++) {
            spheres[i] = new Sphere(new Vec3(3 * i + 0.5, 0.5, 0.5), 0.5);
            spheres[i].bounds().copyTo(boxes, 6 * i);
        }
        for (int count : new int[] {n, 5}) {
            Bvh bvh = Bvh.build(java.util.Arrays.copyOf(boxes, 6 * count), count);
            Traversal traversal = new Traversal(bvh.bounds(), bvh.nodes(), new ShapeLeaves(spheres, bvh.primitives()));
            Hit hit = new Hit();
            hit.primitive = ShapeLeaves.NONE;
            Ray ray = new Ray(-5, 0.5, 0.5, 1, 0, 0);
            double far = Double.POSITIVE_INFINITY;
            traversal.nearest(ray, far, far, hit, hit.sceneStack, hit.sceneStackEntry, hit.sceneWide);
            assertEquals(0, hit.primitive);
            assertEquals(5, hit.t, 1e-12);
            assertFalse(traversal.any(ray, 4.9, ray.sceneWide()));
            assertTrue(traversal.any(ray, 5.1, ray.sceneWide()));
            hit.primitive = ShapeLeaves.NONE;
            Ray last = new Ray(3 * count - 2.5, 0.5, 3, 0, 0, -1);
            traversal.nearest(last, far, far, hit, hit.sceneStack, hit.sceneStackEntry, hit.sceneWide);
            assertEquals(count - 1, hit.primitive, "the last of " + count);
            assertEquals(2, hit.t, 1e-12);
            if (WideBoxTests.vectorized()) {
                assertNotNull(hit.sceneWide);
                assertNotNull(ray.sceneWide());
            } else {
                assertNull(hit.sceneWide);
                assertNull(ray.sceneWide());
            }
        }
    }
}

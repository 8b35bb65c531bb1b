package studio.engine.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Shape;
import studio.engine.geometry.Sphere;
import studio.engine.math.Vec3;

/** The traversal finds the nearest and any hit through the tree, and walks the wide tree exactly where the Vector API box test is on, with scratch to match. */
class TraversalWideTest {

    @Test
    void findsHitsAndWalksTheWideTreeExactlyWhenTheVectorPathIsOn() {
        int n = 40;
        Shape[] spheres = new Shape[n];
        double[] boxes = new double[6 * n];
        for (int i = 0; i < n; i++) {
            spheres[i] = new Sphere(new Vec3(3 * i + 0.5, 0.5, 0.5), 0.5);
            spheres[i].bounds().copyTo(boxes, 6 * i);
        }
        Bvh bvh = Bvh.build(boxes, n);
        Traversal traversal = new Traversal(bvh.bounds(), bvh.nodes(), new ShapeLeaves(spheres, bvh.primitives()));
        assertEquals(WideBoxTests.vectorized(), traversal.isWide());
        Bvh small = Bvh.build(java.util.Arrays.copyOf(boxes, 6 * 5), 5);
        assertFalse(new Traversal(small.bounds(), small.nodes(), new ShapeLeaves(spheres, small.primitives())).isWide(),
                "a tree of a few nodes stays binary");
        Hit hit = new Hit();
        hit.primitive = ShapeLeaves.NONE;
        Ray ray = new Ray(-5, 0.5, 0.5, 1, 0, 0);
        double far = Double.POSITIVE_INFINITY;
        traversal.nearest(ray, far, far, hit, hit.sceneStack, hit.sceneStackEntry, hit.sceneWide);
        assertEquals(0, hit.primitive);
        assertEquals(5, hit.t, 1e-12);
        assertFalse(traversal.any(ray, 4.9, ray.sceneWide()));
        assertTrue(traversal.any(ray, 5.1, ray.sceneWide()));
        if (WideBoxTests.vectorized()) {
            assertNotNull(hit.sceneWide);
            assertNotNull(ray.sceneWide());
        } else {
            assertNull(hit.sceneWide);
            assertNull(ray.sceneWide());
        }
    }
}

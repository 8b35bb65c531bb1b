package studio.engine.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.lang.management.ManagementFactory;
import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.geometry.Ray;
import studio.engine.geometry.Shape;
import studio.engine.geometry.Sphere;
import studio.engine.math.Vec3;

/**
 * The traversal's wide walk finds exactly what its binary walk finds over the same leaves (the
 * scene's shapes, a mesh's triangles): the same nearest primitive at the same distance, the same
 * any-hit answer, for rays that graze boxes (along face planes, from origins on faces, edges and
 * corners, with zero components), through this JVM's box test: the scalar one in the default test
 * run, the Vector API's in the {@code vector-path} run.
 */
class WideWalkTest {

    @Test
    void spheresGiveTheSameHitsThroughBothWalks() {
        Random random = new Random(470);
        for (double[] place : new double[][] {{1, 0}, {1, 1e5}, {1e-3, 0}, {1e3, -1e6}}) {
            double scale = place[0], shift = place[1];
            int n = 2_000;
            Shape[] spheres = new Shape[n];
            for (int i = 0; i < n; i++) {
                double[] c = new double[3];
                for (int a = 0; a < 3; a++) {
                    // a grid one time in two, so that boxes share face planes and rays run along them
                    double v = random.nextBoolean() ? Math.floor(random.nextDouble() * 20) * 2 : random.nextDouble() * 40;
                    c[a] = v * scale + shift;
                }
                double radius = (random.nextBoolean() ? 1 : 0.1 + random.nextDouble()) * scale;
                spheres[i] = new Sphere(new Vec3(c[0], c[1], c[2]), radius);
            }
            assertAgree(Walks.ofShapes(spheres), boxes(spheres), random, scale, shift);
        }
    }

    @Test
    void trianglesGiveTheSameHitsThroughBothWalks() {
        Random random = new Random(471);
        int n = 3_000;
        double[] positions = new double[9 * n];
        int[] indices = new int[3 * n];
        for (int t = 0; t < n; t++) {
            double cx = random.nextDouble() * 40, cy = random.nextDouble() * 40, cz = random.nextDouble() * 40;
            int flat = random.nextInt(4); // axis-aligned triangles give flat boxes
            for (int v = 0; v < 3; v++) {
                positions[9 * t + 3 * v] = cx + (flat == 0 ? 0 : random.nextDouble() * 3);
                positions[9 * t + 3 * v + 1] = cy + (flat == 1 ? 0 : random.nextDouble() * 3);
                positions[9 * t + 3 * v + 2] = cz + (flat == 2 ? 0 : random.nextDouble() * 3);
                indices[3 * t + v] = 3 * t + v;
            }
        }
        double[] boxes = new double[6 * n];
        for (int t = 0; t < n; t++) {
            for (int k = 0; k < 3; k++) {
                boxes[6 * t + k] = Math.min(positions[9 * t + k], Math.min(positions[9 * t + 3 + k], positions[9 * t + 6 + k]));
                boxes[6 * t + 3 + k] = Math.max(positions[9 * t + k], Math.max(positions[9 * t + 3 + k], positions[9 * t + 6 + k]));
            }
        }
        assertAgree(Walks.ofTriangles(positions, indices), boxes, random, 1, 0);
    }

    /**
     * Once compiled, both walks allocate nothing: the wide one with the scalar box test everywhere,
     * with the Vector API's from JDK 20, where {@link WideBoxTests} picks it (JDK 17's incubator API,
     * forced on, allocated some 720 bytes a ray here).
     */
    @Test
    void theWalksAndTheBoxTestAllocateNothingOnceCompiled() {
        assumeTrue(!WideBoxTests.vectorized() || Runtime.version().feature() >= 20, "JDK 17's vector API allocates");
        Random random = new Random(472);
        int n = 3_000;
        Shape[] spheres = new Shape[n];
        for (int i = 0; i < n; i++) {
            spheres[i] = new Sphere(new Vec3(random.nextDouble() * 40, random.nextDouble() * 40, random.nextDouble() * 40), 0.3);
        }
        Walks walks = Walks.ofShapes(spheres);
        Traversal[] both = {walks.binary(), walks.wide()};
        Ray[] rays = new Ray[1024];
        for (int i = 0; i < rays.length; i++) {
            rays[i] = new Ray(-5, random.nextDouble() * 40, random.nextDouble() * 40, 1, random.nextGaussian() * 0.3,
                    random.nextGaussian() * 0.3);
        }
        long sink = walk(walks, both, rays, 200_000); // warm-up: compiled before measuring
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long thread = Thread.currentThread().getId();
        long before = threads.getThreadAllocatedBytes(thread);
        sink += walk(walks, both, rays, 100_000);
        long allocated = threads.getThreadAllocatedBytes(thread) - before;
        assertTrue(sink > 0, "some rays hit");
        assertTrue(allocated < 10_000, allocated + " bytes for 100,000 rays through each walk, " + WideBoxTests.get());
    }

    private static long walk(Walks walks, Traversal[] both, Ray[] rays, int count) {
        long found = 0;
        for (int i = 0; i < count; i++) {
            Ray ray = rays[i & (rays.length - 1)];
            for (Traversal walk : both) {
                found += Double.isNaN(walks.nearest(walk, ray, Double.POSITIVE_INFINITY)) ? 0 : 1;
                found += walks.any(walk, ray, 30) ? 1 : 0;
            }
        }
        return found;
    }

    private static double[] boxes(Shape[] shapes) {
        double[] boxes = new double[6 * shapes.length];
        for (int i = 0; i < shapes.length; i++) {
            shapes[i].bounds().copyTo(boxes, 6 * i);
        }
        return boxes;
    }

    /** Rays at random primitives' boxes ({@code boxes}, six doubles each) through both walks. */
    private static void assertAgree(Walks walks, double[] boxes, Random random, double scale, double shift) {
        Traversal binary = walks.binary(), wide = walks.wide();
        Ray ray = new Ray();
        int hits = 0, occluded = 0, rays = 20_000, count = boxes.length / 6;
        for (int i = 0; i < rays; i++) {
            int p = random.nextInt(count);
            // the helper's offsets are for a scene 40 across: the ray is made there and then moved
            double[] box = new double[6];
            for (int a = 0; a < 6; a++) {
                box[a] = (boxes[6 * p + a] - shift) / scale;
            }
            double[] r = WideBoxTestsTest.randomRay(random, box);
            for (int a = 0; a < 3; a++) {
                r[a] = r[a] * scale + shift;
            }
            ray.set(r[0], r[1], r[2], r[3], r[4], r[5]);
            double tMax = random.nextInt(3) == 0 ? (random.nextDouble() * 40 * scale) : Double.POSITIVE_INFINITY;
            double expected = walks.nearest(binary, ray, tMax);
            int primitive = walks.hit.primitive, triangle = walks.hit.triangle;
            boolean blocked = walks.any(binary, ray, tMax);
            hits += Double.isNaN(expected) ? 0 : 1;
            occluded += blocked ? 1 : 0;
            double found = walks.nearest(wide, ray, tMax);
            assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(found), "distance, ray " + i + ": " + ray);
            assertEquals(primitive, walks.hit.primitive, "nearest shape, ray " + i + ": " + ray);
            assertEquals(triangle, walks.hit.triangle, "nearest triangle, ray " + i + ": " + ray);
            assertEquals(blocked, walks.any(wide, ray, tMax), "any hit, ray " + i + ": " + ray);
        }
        assertTrue(hits > rays / 10 && hits < rays, "hits " + hits + " of " + rays + " (scale " + scale + ", shift "
                + shift + ")");
        assertTrue(occluded >= hits / 2, "occluded " + occluded);
    }
}

package studio.engine.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.lang.management.ManagementFactory;
import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.geometry.Ray;

/**
 * The wide tree's walks find exactly what the binary tree's walks find on the same primitives: the
 * same closest primitive at the same distance, the same any-hit answer, for rays that graze boxes
 * (along face planes, from origins on faces, edges and corners, with zero components), through
 * both the scalar and this JVM's box test.
 */
class WideWalkTest {

    @Test
    void spheresGiveTheSameHitsAsTheBinaryWalk() {
        Random random = new Random(470);
        for (double[] place : new double[][] {{1, 0}, {1, 1e5}, {1e-3, 0}, {1e3, -1e6}}) {
            double scale = place[0], shift = place[1];
            int n = 2_000;
            double[] spheres = new double[4 * n];
            for (int i = 0; i < n; i++) {
                for (int a = 0; a < 3; a++) {
                    // a grid one time in two, so that boxes share face planes and rays run along them
                    double c = random.nextBoolean() ? Math.floor(random.nextDouble() * 20) * 2 : random.nextDouble() * 40;
                    spheres[4 * i + a] = c * scale + shift;
                }
                spheres[4 * i + 3] = (random.nextBoolean() ? 1 : 0.1 + random.nextDouble()) * scale;
            }
            assertAgree(new SpherePrimitives(spheres), random, scale, shift);
        }
    }

    @Test
    void trianglesGiveTheSameHitsAsTheBinaryWalk() {
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
        assertAgree(new TrianglePrimitives(positions, indices), random, 1, 0);
    }

    /**
     * Once compiled, a walk allocates nothing: with the scalar box test everywhere, with the Vector
     * API's from JDK 20, where {@link WideBoxTests} picks it (JDK 17's incubator API, forced on,
     * allocated some 720 bytes a ray here).
     */
    @Test
    void theWalksAndTheBoxTestAllocateNothingOnceCompiled() {
        assumeTrue(!WideBoxTests.vectorized() || Runtime.version().feature() >= 20, "JDK 17's vector API allocates");
        Random random = new Random(472);
        int n = 3_000;
        double[] spheres = new double[4 * n];
        for (int i = 0; i < 4 * n; i++) {
            spheres[i] = i % 4 == 3 ? 0.3 : random.nextDouble() * 40;
        }
        SpherePrimitives leaves = new SpherePrimitives(spheres);
        WideWalk walk = new WideWalk(WideBvh.of(Bvh.build(leaves.boxes(), n)), leaves);
        Ray[] rays = new Ray[1024];
        for (int i = 0; i < rays.length; i++) {
            rays[i] = new Ray(-5, random.nextDouble() * 40, random.nextDouble() * 40, 1, random.nextGaussian() * 0.3,
                    random.nextGaussian() * 0.3);
        }
        long sink = walks(walk, rays, 200_000); // warm-up: compiled before measuring
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long thread = Thread.currentThread().getId();
        long before = threads.getThreadAllocatedBytes(thread);
        sink += walks(walk, rays, 100_000);
        long allocated = threads.getThreadAllocatedBytes(thread) - before;
        assertTrue(sink > 0, "some rays hit");
        assertTrue(allocated < 10_000, allocated + " bytes for 100,000 rays through " + WideBoxTests.get());
    }

    private static long walks(WideWalk walk, Ray[] rays, int count) {
        long found = 0;
        for (int i = 0; i < count; i++) {
            Ray ray = rays[i & (rays.length - 1)];
            found += walk.closest(ray, Double.POSITIVE_INFINITY) >= 0 ? 1 : 0;
            found += walk.occluded(ray, 30) ? 1 : 0;
        }
        return found;
    }

    private static void assertAgree(Primitives leaves, Random random, double scale, double shift) {
        Bvh bvh = Bvh.build(leaves.boxes(), leaves.count());
        WideBvh wide = WideBvh.of(bvh);
        BinaryWalk binary = new BinaryWalk(bvh, leaves);
        WideWalk[] walks = {new WideWalk(wide, leaves, new ScalarBoxTest()), new WideWalk(wide, leaves)};
        Ray ray = new Ray();
        int hits = 0, occluded = 0, rays = 20_000;
        for (int i = 0; i < rays; i++) {
            int p = random.nextInt(leaves.count());
            // the helper's offsets are for a scene 40 across: the ray is made there and then moved
            double[] box = new double[6];
            for (int a = 0; a < 6; a++) {
                box[a] = (leaves.boxes()[6 * p + a] - shift) / scale;
            }
            double[] r = WideBoxTestsTest.randomRay(random, box);
            for (int a = 0; a < 3; a++) {
                r[a] = r[a] * scale + shift;
            }
            ray.set(r[0], r[1], r[2], r[3], r[4], r[5]);
            double tMax = random.nextInt(3) == 0 ? (random.nextDouble() * 40 * scale) : Double.POSITIVE_INFINITY;
            int expected = binary.closest(ray, tMax);
            boolean blocked = binary.occluded(ray, tMax);
            hits += expected >= 0 ? 1 : 0;
            occluded += blocked ? 1 : 0;
            for (WideWalk walk : walks) {
                int found = walk.closest(ray, tMax);
                assertEquals(expected, found, "closest primitive, ray " + i + ": " + ray);
                if (expected >= 0) {
                    assertEquals(Double.doubleToRawLongBits(binary.t), Double.doubleToRawLongBits(walk.t), "distance");
                }
                assertEquals(blocked, walk.occluded(ray, tMax), "any hit, ray " + i + ": " + ray);
            }
        }
        assertTrue(hits > rays / 10 && hits < rays, "hits " + hits + " of " + rays + " (scale " + scale + ", shift "
                + shift + ")");
        assertTrue(occluded >= hits / 2, "occluded " + occluded);
    }
}

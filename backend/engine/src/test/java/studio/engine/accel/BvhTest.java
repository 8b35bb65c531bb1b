package studio.engine.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.memory.CountingGate;

/** The flattened tree's invariants on ordinary and degenerate inputs. */
class BvhTest {

    /** n boxes of half-size below 1 around centres in [0, 100)^3, drawn from random in order. */
    private static double[] randomBoxes(Random random, int n) {
        double[] boxes = new double[6 * n];
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < 3; a++) {
                double c = random.nextDouble() * 100, h = random.nextDouble();
                boxes[6 * i + a] = c - h;
                boxes[6 * i + a + 3] = c + h;
            }
        }
        return boxes;
    }

    @Test
    void randomBoxesGiveAValidTreeWithSmallLeaves() {
        Random random = new Random(1);
        int n = 10_000;
        double[] boxes = randomBoxes(random, n);

        Bvh bvh = Bvh.build(boxes, n);

        assertValid(bvh, boxes, n);
        assertTrue(bvh.depth() < 40, "depth " + bvh.depth());
        assertTrue(bvh.buildNanos() > 0);
    }

    /**
     * The builder's loops over a node's slots run {@value studio.engine.geometry.Runs#LENGTH} slots a call; over 20,000
     * boxes, across many runs (the partition's two ends meeting inside one), the tree is node for
     * node, box for box and slot for slot the one built before they were cut into runs (its hashes,
     * from that build).
     */
    @Test
    void slotLoopsInRunsBuildTheSameTreeAsInOneCall() {
        Random random = new Random(47);
        int n = 20_000;
        double[] boxes = randomBoxes(random, n);

        Bvh bvh = Bvh.build(boxes, n);

        assertEquals(39_521, bvh.nodeCount());
        assertEquals(-632_126_585, Arrays.hashCode(Arrays.copyOf(bvh.nodes(), 3 * bvh.nodeCount())));
        assertEquals(-453_360_321, Arrays.hashCode(Arrays.copyOf(bvh.bounds(), 6 * bvh.nodeCount())));
        assertEquals(-1_813_202_321, Arrays.hashCode(bvh.primitives()));
    }

    @Test
    void buildAsksTheGateForWhatItAllocates() {
        Random random = new Random(2);
        Bvh.build(new double[6], 1); // loads and initialises what the first build needs
        for (int n : new int[] {1, 7, 200_000}) {
            double[] boxes = randomBoxes(random, n);
            CountingGate gate = new CountingGate();
            long allocated = CountingGate.allocatedBy(() -> Bvh.build(boxes, n, gate));

            assertTrue(allocated <= gate.granted() + CountingGate.SLACK, n + ": " + allocated + " allocated, "
                    + gate.granted() + " granted");
            assertTrue(n < 1000 || gate.granted() < 1.2 * allocated, n + ": granted " + gate.granted());
            CountingGate stingy = new CountingGate(gate.granted() / 2);
            assertTrue(CountingGate.allocatedBy(() -> Bvh.build(boxes, n, stingy))
                    <= gate.granted() / 2 + CountingGate.SLACK, "a refusal stops the build");
        }
    }

    @Test
    void coincidentCentroidsFallBackToMedianSplitsWithLeavesOfAtMostFour() {
        int n = 1000;
        double[] boxes = new double[6 * n];
        for (int i = 0; i < n; i++) {
            // all centred at the origin, different sizes: SAH has nothing to bin
            double h = 1 + i;
            boxes[6 * i] = boxes[6 * i + 1] = boxes[6 * i + 2] = -h;
            boxes[6 * i + 3] = boxes[6 * i + 4] = boxes[6 * i + 5] = h;
        }

        Bvh bvh = Bvh.build(boxes, n);

        assertValid(bvh, boxes, n);
        assertTrue(bvh.depth() <= 12, "median splits halve the count: depth " + bvh.depth());
    }

    @Test
    void exponentiallySpacedBoxesStayWithinTheTraversalStack() {
        // SAH peels one box off per level here; the depth limit then switches to median splits.
        int n = 2000;
        double[] boxes = new double[6 * n];
        for (int i = 0; i < n; i++) {
            double x = Math.pow(1.4, i % 1000) * (i < 1000 ? 1 : -1);
            double h = Math.abs(x) * 1e-3;
            boxes[6 * i] = x - h;
            boxes[6 * i + 3] = x + h;
            boxes[6 * i + 4] = boxes[6 * i + 5] = 1;
        }

        Bvh bvh = Bvh.build(boxes, n);

        assertValid(bvh, boxes, n);
        assertTrue(bvh.depth() <= Bvh.STACK_SIZE, "depth " + bvh.depth());
    }

    @Test
    void onePrimitiveIsOneLeaf() {
        double[] box = {1, 2, 3, 4, 5, 6};

        Bvh bvh = Bvh.build(box, 1);

        assertEquals(1, bvh.nodeCount());
        assertEquals(new Aabb(1, 2, 3, 4, 5, 6), bvh.rootBounds());
        assertValid(bvh, box, 1);
    }

    @Test
    void rejectsNoPrimitivesAndNonFiniteBoxes() {
        assertThrows(IllegalArgumentException.class, () -> Bvh.build(new double[0], 0));
        assertThrows(IllegalArgumentException.class,
                () -> Bvh.build(new double[] {0, 0, 0, 1, Double.NaN, 1}, 1));
    }

    /**
     * Every primitive in exactly one leaf of 1..4; every box inside its parent's; left child next,
     * right child and escape index consistent with depth-first order.
     */
    static void assertValid(Bvh bvh, double[] boxes, int n) {
        int[] seen = new int[n];
        int end = check(bvh, 0, boxes, seen, 1);
        assertEquals(bvh.nodeCount(), end, "nodes after the root's subtree");
        for (int i = 0; i < n; i++) {
            assertEquals(1, seen[i], "leaves holding primitive " + i);
        }
    }

    /** Checks the subtree at node; returns the index after it. */
    private static int check(Bvh bvh, int node, double[] boxes, int[] seen, int depth) {
        int[] links = bvh.nodes();
        double[] b = bvh.bounds();
        assertTrue(depth <= bvh.depth());
        int count = links[3 * node + 1];
        int after;
        if (count > 0) {
            assertTrue(count <= Bvh.LEAF_MAX, "leaf of " + count);
            for (int slot = links[3 * node]; slot < links[3 * node] + count; slot++) {
                int p = bvh.primitives()[slot];
                seen[p]++;
                assertInside(boxes, 6 * p, b, 6 * node);
            }
            after = node + 1;
        } else {
            int right = links[3 * node];
            assertInside(b, 6 * (node + 1), b, 6 * node);
            assertInside(b, 6 * right, b, 6 * node);
            assertEquals(right, check(bvh, node + 1, boxes, seen, depth + 1), "right child follows the left subtree");
            after = check(bvh, right, boxes, seen, depth + 1);
        }
        assertEquals(after, links[3 * node + 2], "escape index of node " + node);
        return after;
    }

    private static void assertInside(double[] inner, int i, double[] outer, int o) {
        for (int a = 0; a < 3; a++) {
            assertTrue(outer[o + a] <= inner[i + a] && inner[i + a + 3] <= outer[o + a + 3]);
        }
    }
}

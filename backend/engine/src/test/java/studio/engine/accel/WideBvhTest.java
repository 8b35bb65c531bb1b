package studio.engine.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

/** The collapse from a binary tree: every primitive kept once, boxes rounded outward, the same leaves. */
class WideBvhTest {

    @Test
    void collapseKeepsEveryBinaryLeafAndEveryPrimitiveExactlyOnce() {
        Random random = new Random(47);
        for (int n : new int[] {1, 2, 3, 4, 5, 9, 17, 100, 1000, 20_000}) {
            double[] boxes = randomBoxes(random, n, 100, 1);
            Bvh bvh = Bvh.build(boxes, n);
            WideBvh wide = WideBvh.of(bvh);
            assertCollapsed(bvh, wide, boxes, n);
        }
    }

    @Test
    void degenerateTreesCollapseToo() {
        int n = 300;
        double[] same = new double[6 * n];
        double[] spread = new double[6 * n];
        for (int i = 0; i < n; i++) {
            new Aabb(1, 2, 3, 4, 5, 6).copyTo(same, 6 * i);
            double c = Math.pow(1.2, i);
            new Aabb(c, 0, 0, c * 1.1, 1, 1).copyTo(spread, 6 * i);
        }
        for (double[] boxes : new double[][] {same, spread}) {
            Bvh bvh = Bvh.build(boxes, n);
            assertCollapsed(bvh, WideBvh.of(bvh), boxes, n);
        }
    }

    @Test
    void coordinatesBeyondTheFloatRangeRoundOutwardToInfinity() {
        double[] boxes = {-1e40, 0, 0, 1, 1, 1, 5, 5, 5, 1e300, 6, 6, 0.1, 0.1, 0.1, 0.2, 0.2, 0.2};
        Bvh bvh = Bvh.build(boxes, 3);
        WideBvh wide = WideBvh.of(bvh);
        assertCollapsed(bvh, wide, boxes, 3);
        float[] b = wide.boxes();
        boolean negative = false, positive = false;
        for (int k = 0; k < WideBvh.WIDTH; k++) {
            negative |= b[WideBvh.MIN_X + k] == Float.NEGATIVE_INFINITY;
            positive |= b[WideBvh.MAX_X + k] == Float.POSITIVE_INFINITY;
        }
        assertTrue(negative && positive);
    }

    @Test
    void floatBelowAndAboveAreTheNearestFloatsOnEachSide() {
        Random random = new Random(3);
        for (int i = 0; i < 100_000; i++) {
            double v = (random.nextDouble() - 0.5) * Math.pow(10, random.nextInt(60) - 30);
            float below = WideBvh.floatBelow(v), above = WideBvh.floatAbove(v);
            assertTrue(below <= v && Math.nextUp(below) > v, v + " " + below);
            assertTrue(above >= v && Math.nextDown(above) < v, v + " " + above);
        }
        assertEquals(0.5f, WideBvh.floatBelow(0.5));
        assertEquals(0.5f, WideBvh.floatAbove(0.5));
    }

    @Test
    void leafLinksRoundTrip() {
        for (int first : new int[] {0, 1, 7, 1 << 20, (1 << 28) - 1}) {
            for (int count = 1; count <= Bvh.LEAF_MAX; count++) {
                int link = WideBvh.leaf(first, count);
                assertTrue(WideBvh.isLeaf(link));
                assertEquals(first, WideBvh.leafFirst(link));
                assertEquals(count, WideBvh.leafCount(link));
            }
        }
    }

    static double[] randomBoxes(Random random, int n, double extent, double size) {
        double[] boxes = new double[6 * n];
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < 3; a++) {
                double c = random.nextDouble() * extent, h = random.nextDouble() * size;
                boxes[6 * i + a] = c - h;
                boxes[6 * i + a + 3] = c + h;
            }
        }
        return boxes;
    }

    private static void assertCollapsed(Bvh bvh, WideBvh wide, double[] boxes, int n) {
        List<Long> binaryLeaves = new ArrayList<>();
        int[] links = bvh.nodes();
        for (int i = 0; i < bvh.nodeCount(); i++) {
            if (links[3 * i + 1] > 0) {
                binaryLeaves.add((long) links[3 * i] << 8 | links[3 * i + 1]);
            }
        }
        List<Long> wideLeaves = new ArrayList<>();
        int[] slotSeen = new int[n];
        int[] nodeSeen = new int[wide.nodeCount()];
        int depth = visit(wide, 0, boxes, wideLeaves, slotSeen, nodeSeen, 1);
        binaryLeaves.sort(null);
        wideLeaves.sort(null);
        assertEquals(binaryLeaves, wideLeaves, "the wide leaves are the binary leaves");
        for (int s = 0; s < n; s++) {
            assertEquals(1, slotSeen[s], "slot " + s);
        }
        for (int i = 0; i < wide.nodeCount(); i++) {
            assertEquals(1, nodeSeen[i], "node " + i + " is reached once");
        }
        assertEquals(depth, wide.depth());
        assertTrue(wide.depth() <= bvh.depth(), wide.depth() + " > " + bvh.depth());
        assertTrue(wide.primitives() == bvh.primitives());
    }

    /** Checks node {@code node} and below; returns the depth of its subtree's deepest node, counting from {@code level}. */
    private static int visit(WideBvh wide, int node, double[] boxes, List<Long> leaves, int[] slotSeen, int[] nodeSeen,
                             int level) {
        nodeSeen[node]++;
        float[] b = wide.boxes();
        int base = WideBvh.FLOATS * node;
        int used = 0, depth = level;
        for (int k = 0; k < WideBvh.WIDTH; k++) {
            int link = wide.children()[WideBvh.WIDTH * node + k];
            if (link == WideBvh.EMPTY) {
                for (int a = 0; a < 3; a++) {
                    assertEquals(Float.POSITIVE_INFINITY, b[base + WideBvh.MIN_X + WideBvh.WIDTH * a + k]);
                    assertEquals(Float.NEGATIVE_INFINITY, b[base + WideBvh.MAX_X + WideBvh.WIDTH * a + k]);
                }
                continue;
            }
            used++;
            List<Integer> under = new ArrayList<>();
            if (WideBvh.isLeaf(link)) {
                leaves.add((long) WideBvh.leafFirst(link) << 8 | WideBvh.leafCount(link));
                for (int s = WideBvh.leafFirst(link), e = s + WideBvh.leafCount(link); s < e; s++) {
                    slotSeen[s]++;
                    under.add(wide.primitives()[s]);
                }
            } else {
                assertTrue(link > node, "children come after their parent");
                depth = Math.max(depth, visit(wide, link, boxes, leaves, slotSeen, nodeSeen, level + 1));
                collect(wide, link, under);
            }
            for (int p : under) {
                for (int a = 0; a < 3; a++) {
                    assertTrue(b[base + WideBvh.MIN_X + WideBvh.WIDTH * a + k] <= boxes[6 * p + a], "min contains primitive " + p);
                    assertTrue(b[base + WideBvh.MAX_X + WideBvh.WIDTH * a + k] >= boxes[6 * p + a + 3], "max contains primitive " + p);
                }
            }
        }
        assertTrue(used >= 2 || (node == 0 && used == 1 && wide.nodeCount() == 1), "node " + node + " uses " + used);
        return depth;
    }

    private static void collect(WideBvh wide, int node, List<Integer> out) {
        for (int k = 0; k < WideBvh.WIDTH; k++) {
            int link = wide.children()[WideBvh.WIDTH * node + k];
            if (WideBvh.isLeaf(link)) {
                for (int s = WideBvh.leafFirst(link), e = s + WideBvh.leafCount(link); s < e; s++) {
                    out.add(wide.primitives()[s]);
                }
            } else if (link != WideBvh.EMPTY) {
                collect(wide, link, out);
            }
        }
    }
}

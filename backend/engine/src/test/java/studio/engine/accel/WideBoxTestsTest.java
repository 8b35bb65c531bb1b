package studio.engine.accel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * The eight-box tests: conservative against the double {@link Slab} test (robustness cases NUM-04
 * and NUM-06), the scalar and vector paths bit for bit the same, and the choice between them. The
 * build runs this class twice: as it is, and with the Vector API forced on.
 */
class WideBoxTestsTest {

    private static final WideBoxTest SCALAR = new ScalarBoxTest();
    private final float[] entry = new float[WideBvh.WIDTH];
    private final WideRay ray = new WideRay();

    @Test
    void theChoiceFollowsTheSystemPropertyAndTheModule() {
        assertInstanceOf(ScalarBoxTest.class, WideBoxTests.choose("off"));
        boolean hasModule = ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent();
        if (hasModule) {
            assertEquals("VectorBoxTest", WideBoxTests.choose("on").getClass().getSimpleName());
        } else {
            assertThrows(IllegalStateException.class, () -> WideBoxTests.choose("on"));
            assertInstanceOf(ScalarBoxTest.class, WideBoxTests.choose("auto"), "without the module: scalar");
        }
        String forced = System.getProperty(WideBoxTests.PROPERTY, "");
        if (forced.equals("on")) {
            assertTrue(WideBoxTests.vectorized());
        } else if (forced.equals("off")) {
            assertTrue(!WideBoxTests.vectorized());
        }
    }

    @Test
    void vectorAndScalarGiveTheSameMasksAndEntriesBitForBit() {
        assumeTrue(WideBoxTests.vectorized(), "the vector path runs in the build's vector-path execution");
        WideBoxTest vector = WideBoxTests.get();
        Random random = new Random(11);
        float[] entryVector = new float[WideBvh.WIDTH];
        int hits = 0;
        for (int i = 0; i < 200_000; i++) {
            double[][] boxes = new double[WideBvh.WIDTH][];
            for (int k = 0; k < WideBvh.WIDTH; k++) {
                boxes[k] = randomBox(random);
            }
            float[] node = node(boxes, random.nextInt(5) == 0 ? random.nextInt(WideBvh.WIDTH) : WideBvh.WIDTH);
            double[] r = randomRay(random, boxes[random.nextInt(WideBvh.WIDTH)]);
            ray.set(r[0], r[1], r[2], r[3], r[4], r[5]);
            float limit = WideRay.limit(random.nextBoolean() ? Double.POSITIVE_INFINITY : random.nextDouble() * 30);
            int a = SCALAR.test(node, 0, ray, limit, entry);
            int b = vector.test(node, 0, ray, limit, entryVector);
            assertEquals(a, b, "mask of case " + i);
            for (int k = 0; k < WideBvh.WIDTH; k++) {
                assertEquals(Float.floatToRawIntBits(entry[k]), Float.floatToRawIntBits(entryVector[k]), "entry " + k);
            }
            hits += Integer.bitCount(a);
        }
        assertTrue(hits > 20_000, "enough lanes hit to compare entries: " + hits);
    }

    @Test
    void keepsEveryBoxTheDoubleTestKeepsEvenWhenTheLimitIsTheEntryItself() {
        Random random = new Random(12);
        int kept = 0;
        for (int i = 0; i < 200_000; i++) {
            double[] box = randomBox(random);
            double[] r = randomRay(random, box);
            double ix = 1 / r[3], iy = 1 / r[4], iz = 1 / r[5];
            double tMax = random.nextBoolean() ? Double.POSITIVE_INFINITY : random.nextDouble() * 30;
            double in = Slab.entry(box, 0, r[0], r[1], r[2], ix, iy, iz, tMax);
            if (Double.isNaN(in)) {
                continue;
            }
            kept++;
            ray.set(r[0], r[1], r[2], r[3], r[4], r[5]);
            float[] node = node(new double[][] {box, box, box, box}, 4);
            for (double limit : new double[] {tMax, in}) {
                int mask = WideBoxTests.get().test(node, 0, ray, WideRay.limit(limit), entry);
                assertEquals(0b1111, mask, "case " + i + " with limit " + limit);
                assertEquals(mask, SCALAR.test(node, 0, ray, WideRay.limit(limit), entry));
            }
        }
        assertTrue(kept > 30_000, "boxes met: " + kept);
    }

    @Test
    void rayInABoxFacePlaneNum04IsKept() {
        double[][] boxes = {
                {3.223, 0.241, 2.119, 3.225, 0.243, 2.121}, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}};
        double[][] origins = {{3.225, 0.243, 2.221}, {0.5, 1, 3}, {0, 0.5, 3}, {0.5, 1.5, 3}};
        boolean[] expected = {true, true, true, false};
        for (int c = 0; c < 4; c++) {
            float[] node = node(new double[][] {boxes[c], boxes[c], boxes[c], boxes[c]}, 4);
            ray.set(origins[c][0], origins[c][1], origins[c][2], 0, 0, -1);
            int mask = WideBoxTests.get().test(node, 0, ray, WideRay.limit(Double.POSITIVE_INFINITY), entry);
            assertEquals(expected[c] ? 0b1111 : 0, mask, "NUM-04 case " + (c + 1));
            if (expected[c]) {
                assertTrue(entry[0] <= (c == 0 ? 0.1 : 2.0) && entry[0] > (c == 0 ? 0.09 : 1.99), "entry " + entry[0]);
            }
        }
    }

    @Test
    void flatBoxAndEdgeTouchingRaysNum06AreKept() {
        float[] flat = node(new double[][] {{-1, -1, -5, 1, 1, -5}, {-1, -1, -5, 1, 1, -5}, {-1, -1, -5, 1, 1, -5},
                {-1, -1, -5, 1, 1, -5}}, 4);
        for (int i = 0; i <= 20; i++) {
            for (int j = 0; j <= 20; j++) {
                ray.set(0, 0, 0, -0.15 + 0.015 * i, -0.15 + 0.015 * j, -1);
                assertEquals(0b1111, WideBoxTests.get().test(flat, 0, ray, WideRay.limit(Double.POSITIVE_INFINITY), entry));
            }
        }
        double[] box = {-0.37, 0.21, -1.13, 0.61, 1.07, -0.29};
        float[] node = node(new double[][] {box, box, box, box}, 4);
        Random random = new Random(6);
        for (int i = 0; i < 20_000; i++) {
            double pz = box[2] + (box[5] - box[2]) * random.nextDouble();
            double a = 0.2 + 0.8 * random.nextDouble(), b = 0.2 + 0.8 * random.nextDouble(),
                    c = -0.3 + 0.6 * random.nextDouble();
            double len = Math.sqrt(a * a + b * b + c * c), s = 0.5 + 49.5 * random.nextDouble();
            double dx = a / len, dy = -b / len, dz = c / len;
            ray.set(0.61 - s * dx, 1.07 - s * dy, pz - s * dz, dx, dy, dz);
            assertEquals(0b1111, WideBoxTests.get().test(node, 0, ray, WideRay.limit(Double.POSITIVE_INFINITY), entry),
                    "edge-touching ray " + i);
        }
    }

    @Test
    void emptyLanesAreNeverMetAndRaysOutsideTheFloatBoundsKeepEverything() {
        float[] node = node(new double[][] {{0, 0, 0, 1, 1, 1}, {5, 5, 5, 6, 6, 6}, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}}, 2);
        ray.set(0.5, 0.5, -1, 0, 0, 1);
        assertEquals(0b0001, WideBoxTests.get().test(node, 0, ray, WideRay.limit(Double.POSITIVE_INFINITY), entry));
        ray.set(0, 0, 0, 1, -1, 1);
        assertEquals(0b0001, WideBoxTests.get().test(node, 0, ray, WideRay.limit(Double.POSITIVE_INFINITY), entry),
                "the corner at the origin is met, the empty lanes are not");
        for (double[] r : new double[][] {{0, 0, -1, 1e-35, 0, 1}, {0, 0, -1, 1e31, 1, 1}, {1e31, 0, 0, 0, 0, 1}}) {
            ray.set(r[0], r[1], r[2], r[3], r[4], r[5]);
            assertTrue(ray.acceptAll);
            assertEquals(WideBvh.ALL_LANES, WideBoxTests.get().test(node, 0, ray, WideRay.limit(1), entry));
        }
        ray.set(0, 0, 0, 0, 0, 1);
        assertTrue(!ray.acceptAll, "zero components are handled exactly");
    }

    /** A node of the given boxes in its first {@code used} lanes, the rest empty. */
    static float[] node(double[][] boxes, int used) {
        float[] node = new float[WideBvh.FLOATS];
        for (int k = 0; k < WideBvh.WIDTH; k++) {
            for (int a = 0; a < 3; a++) {
                node[WideBvh.MIN_X + WideBvh.WIDTH * a + k] = k < used ? WideBvh.floatBelow(boxes[k][a]) : Float.POSITIVE_INFINITY;
                node[WideBvh.MAX_X + WideBvh.WIDTH * a + k] = k < used ? WideBvh.floatAbove(boxes[k][a + 3]) : Float.NEGATIVE_INFINITY;
            }
        }
        return node;
    }

    /** A box of size 1e-3 to 10 somewhere in [-20, 20]^3, flat on one axis one time in five. */
    private static double[] randomBox(Random random) {
        double[] box = new double[6];
        int flat = random.nextInt(15);
        for (int a = 0; a < 3; a++) {
            double c = 40 * random.nextDouble() - 20, h = Math.pow(10, 4 * random.nextDouble() - 3);
            box[a] = c - h;
            box[a + 3] = a == flat ? c - h : c + h;
        }
        return box;
    }

    /**
     * A ray that has a fair chance to graze {@code box}: from a random point or from a point on one
     * of its faces, edges or corners, along a random direction, an axis, or a direction in a face's
     * plane, with zero (and negative zero) components.
     */
    static double[] randomRay(Random random, double[] box) {
        double[] o = new double[3], d = new double[3];
        for (int a = 0; a < 3; a++) {
            switch (random.nextInt(4)) {
                case 0 -> o[a] = box[a];
                case 1 -> o[a] = box[a + 3];
                default -> o[a] = box[a] + (box[a + 3] - box[a]) * (3 * random.nextDouble() - 1);
            }
            if (random.nextInt(6) == 0) {
                o[a] += (random.nextDouble() - 0.5) * 40;
            }
            d[a] = switch (random.nextInt(5)) {
                case 0 -> 0.0;
                case 1 -> -0.0;
                default -> random.nextGaussian();
            };
        }
        if (d[0] == 0 && d[1] == 0 && d[2] == 0) {
            d[random.nextInt(3)] = random.nextBoolean() ? 1 : -1;
        }
        // step back along the ray one time in two, so the ray meets the point from outside
        if (random.nextBoolean()) {
            double s = 30 * random.nextDouble();
            for (int a = 0; a < 3; a++) {
                o[a] -= s * d[a];
            }
        }
        return new double[] {o[0], o[1], o[2], d[0], d[1], d[2]};
    }
}

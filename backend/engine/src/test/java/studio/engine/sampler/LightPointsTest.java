package studio.engine.sampler;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;

import org.junit.jupiter.api.Test;

class LightPointsTest {

    /** The light points of pixel (x, y)'s run first .. first + count - 1, as {u..., v...}. */
    private static double[][] run(Sampler sampler, int x, int y, int first, int count, long seed) {
        PixelSamples pixel = new PixelSamples(sampler, sampler.samplesPerPixel(), seed);
        double[] xs = new double[sampler.samplesPerPixel()], ys = new double[sampler.samplesPerPixel()];
        pixel.startPixel(x, y);
        pixel.fill(first, count, xs, ys);
        LightPoints points = new LightPoints(sampler, seed);
        points.start(x, y, first, count, xs, ys);
        double[] u = new double[count], v = new double[count];
        for (int s = first; s < first + count; s++) {
            u[s - first] = points.u(s);
            v[s - first] = points.v(s);
        }
        return new double[][] {u, v, Arrays.copyOfRange(xs, first, first + count), Arrays.copyOfRange(ys, first, first + count)};
    }

    /** Under jittered, 16 light points are a 4 x 4 stratification and also one point in each of 16 narrow columns and rows. */
    @Test
    void jitteredGivesTheLightAMultiJitteredPattern() {
        for (int pixel = 0; pixel < 50; pixel++) {
            double[][] r = run(new JitteredSampler(16), pixel, 3, 0, 16, 7L);
            boolean[] cell = new boolean[16], column = new boolean[16], row = new boolean[16];
            for (int s = 0; s < 16; s++) {
                double u = r[0][s], v = r[1][s];
                assertTrue(u >= 0 && u < 1 && v >= 0 && v < 1);
                cell[(int) (u * 4) + 4 * (int) (v * 4)] = true;
                column[(int) (u * 16)] = true;
                row[(int) (v * 16)] = true;
            }
            for (int k = 0; k < 16; k++) {
                assertTrue(cell[k] && column[k] && row[k], "pixel " + pixel + ": stratum " + k);
            }
        }
    }

    /** Under jittered the light points are drawn apart from the pixel points: no sample's light point is its own place in the pixel. */
    @Test
    void jitteredLightPointsAreNotThePixelPoints() {
        double sumXu = 0, sumX = 0, sumU = 0;
        int n = 0;
        for (int pixel = 0; pixel < 400; pixel++) {
            double[][] r = run(new JitteredSampler(16), pixel % 20, pixel / 20, 0, 16, 3L);
            for (int s = 0; s < 16; s++) {
                assertNotEquals(r[2][s], r[0][s]);
                sumXu += r[2][s] * r[0][s];
                sumX += r[2][s];
                sumU += r[0][s];
                n++;
            }
        }
        double covariance = sumXu / n - (sumX / n) * (sumU / n);
        assertEquals(0, covariance / (1 / 12.0), 0.03, "correlation of a sample's x in the pixel and its u on the light");
    }

    /** Under sobol a run's light points are its own pixel points in another order (a net stays a net). */
    @Test
    void sobolDealsTheRunsOwnPixelPoints() {
        double[][] r = run(new SobolSampler(16), 5, 9, 8, 8, 11L);
        double[] u = r[0].clone(), x = r[2].clone(), v = r[1].clone(), y = r[3].clone();
        Arrays.sort(u);
        Arrays.sort(x);
        Arrays.sort(v);
        Arrays.sort(y);
        assertArrayEquals(x, u);
        assertArrayEquals(y, v);
        assertTrue(!Arrays.equals(r[0], r[2]), "shuffled");
    }

    /**
     * Under sobol a run's pixel and light points are stratified together: in the first 4 samples
     * (runs 1, 1, 2) every pair of halves (x, u) and (y, v) holds one sample, and so does every pair
     * of halves (x, u) in the run of 4 after them.
     */
    @Test
    void sobolPairsAPixelPointWithALightPointOfAnotherStratum() {
        Sampler sampler = new SobolSampler(16);
        for (int pixel = 0; pixel < 64; pixel++) {
            int px = pixel % 8, py = pixel / 8;
            double[] x = new double[8], y = new double[8], u = new double[8], v = new double[8];
            int[][] runs = {{0, 1}, {1, 1}, {2, 2}, {4, 4}};
            for (int[] run : runs) {
                double[][] r = run(sampler, px, py, run[0], run[1], 5L);
                for (int s = 0; s < run[1]; s++) {
                    u[run[0] + s] = r[0][s];
                    v[run[0] + s] = r[1][s];
                    x[run[0] + s] = r[2][s];
                    y[run[0] + s] = r[3][s];
                }
            }
            assertStrata(x, u, 0, 4, 2, 2, "pixel " + pixel + ", (x, u)");
            assertStrata(y, v, 0, 4, 2, 2, "pixel " + pixel + ", (y, v)");
            assertStrata(x, u, 4, 4, 2, 2, "pixel " + pixel + ", run of 4, (x, u)");
        }
    }

    private static void assertStrata(double[] a, double[] b, int first, int count, int aCells, int bCells, String what) {
        boolean[] seen = new boolean[aCells * bCells];
        for (int s = first; s < first + count; s++) {
            int cell = (int) (a[s] * aCells) * bCells + (int) (b[s] * bCells);
            assertTrue(!seen[cell], what + ": two samples in stratum " + cell);
            seen[cell] = true;
        }
    }

    /** A pixel's light points depend on the pixel, the run and the seed only: asked again, or after other pixels, they are the same. */
    @Test
    void lightPointsAreTheSameWhateverCameBefore() {
        Sampler sampler = new JitteredSampler(16);
        double[][] first = run(sampler, 4, 4, 0, 16, 9L);
        LightPoints points = new LightPoints(sampler, 9L);
        double[] xs = new double[16], ys = new double[16];
        points.start(1, 2, 0, 16, xs, ys);
        PixelSamples pixel = new PixelSamples(sampler, 16, 9L);
        pixel.startPixel(4, 4);
        pixel.fill(0, 16, xs, ys);
        points.start(4, 4, 0, 16, xs, ys);
        for (int s = 0; s < 16; s++) {
            assertEquals(first[0][s], points.u(s));
            assertEquals(first[1][s], points.v(s));
        }
        assertNotEquals(first[0][0], run(sampler, 5, 4, 0, 16, 9L)[0][0]);
    }

    /** An empty run (an adaptive pixel already at its limit) is accepted: there is no pattern of 0 points to draw. */
    @Test
    void anEmptyRunIsAccepted() {
        for (Sampler sampler : new Sampler[] {new JitteredSampler(16), new SobolSampler(16)}) {
            LightPoints points = new LightPoints(sampler, 1L);
            assertDoesNotThrow(() -> points.start(0, 0, 16, 0, new double[16], new double[16]));
        }
    }

    /** Dealing a run's light points, multi-jittered or the pixel's own, allocates nothing (it runs once per pixel run, in the hot loop). */
    @Test
    void dealingLightPointsAllocatesNothing() {
        for (Sampler sampler : new Sampler[] {new JitteredSampler(64), new SobolSampler(64)}) {
            LightPoints points = new LightPoints(sampler, 4L);
            double[] xs = new double[64], ys = new double[64];
            double sum = deal(points, xs, ys); // warm-up: lets the JIT compile the loop
            sum += deal(points, xs, ys);
            com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
            long thread = Thread.currentThread().getId();
            long before = threads.getThreadAllocatedBytes(thread);
            sum += deal(points, xs, ys);
            long bytes = threads.getThreadAllocatedBytes(thread) - before;
            assertTrue(bytes < 4096, sampler.name() + ": allocated " + bytes + " bytes");
            assertTrue(Double.isFinite(sum));
        }
    }

    private static double deal(LightPoints points, double[] xs, double[] ys) {
        double sum = 0;
        for (int pixel = 0; pixel < 20_000; pixel++) {
            int first = pixel % 3 == 0 ? 0 : 16, count = pixel % 3 == 0 ? 16 : 48;
            points.start(pixel % 97, pixel / 97, first, count, xs, ys);
            sum += points.u(first) + points.v(first + count - 1);
        }
        return sum;
    }
}

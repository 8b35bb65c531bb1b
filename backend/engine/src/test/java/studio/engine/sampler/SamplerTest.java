package studio.engine.sampler;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;

import org.junit.jupiter.api.Test;

class SamplerTest {

    @Test
    void regularSamplerGivesTheCentresOfAKByKGrid() {
        for (int k = 1; k <= 5; k++) {
            int n = k * k;
            double[] xs = new double[n], ys = new double[n];

            new RegularSampler(n).generate(new PixelRandom(), xs, ys);

            boolean[][] seen = new boolean[k][k];
            for (int i = 0; i < n; i++) {
                int column = (int) Math.floor(xs[i] * k), row = (int) Math.floor(ys[i] * k);
                assertEquals((column + 0.5) / k, xs[i], 1e-15, "x of sample " + i + " at N=" + n);
                assertEquals((row + 0.5) / k, ys[i], 1e-15, "y of sample " + i + " at N=" + n);
                assertFalse(seen[row][column], "cell used twice at N=" + n);
                seen[row][column] = true;
            }
        }
    }

    @Test
    void regularSamplerWithOneSampleUsesThePixelCentre() {
        double[] xs = new double[1], ys = new double[1];

        new RegularSampler(1).generate(new PixelRandom(), xs, ys);

        assertEquals(0.5, xs[0], 0.0);
        assertEquals(0.5, ys[0], 0.0);
    }

    @Test
    void regularSamplerRejectsNonSquareCounts() {
        for (int n : new int[] {0, -4, 2, 3, 5, 8, 12, 15, 17}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new RegularSampler(n),
                    "N=" + n);
            assertTrue(e.getMessage().contains("square"), e.getMessage());
        }
    }

    @Test
    void jitteredSamplerPutsExactlyOneSampleInEachOf16Strata() {
        assertOneSamplePerStratum(16, 4, 4);
    }

    @Test
    void jitteredSamplerPutsExactlyOneSampleInEachOf12StrataOfThreeRowsByFourColumns() {
        assertOneSamplePerStratum(12, 3, 4);
    }

    @Test
    void jitteredSamplerWithAPrimeCountUsesOneRow() {
        assertOneSamplePerStratum(7, 1, 7);
    }

    private static void assertOneSamplePerStratum(int n, int rows, int columns) {
        JitteredSampler sampler = new JitteredSampler(n);
        PixelRandom random = new PixelRandom();
        double[] xs = new double[n], ys = new double[n];
        for (int pixel = 0; pixel < 1000; pixel++) {
            random.reset(pixel % 37, pixel / 37, 12345);
            sampler.generate(random, xs, ys);
            int[][] count = new int[rows][columns];
            for (int i = 0; i < n; i++) {
                assertTrue(xs[i] >= 0 && xs[i] < 1 && ys[i] >= 0 && ys[i] < 1);
                count[(int) (ys[i] * rows)][(int) (xs[i] * columns)]++;
            }
            for (int[] row : count) {
                for (int c : row) {
                    assertEquals(1, c, "samples per stratum for N=" + n + ", pixel " + pixel);
                }
            }
        }
    }

    @Test
    void jitteredSamplerIsDeterministicPerPixelAndSeedAndDiffersBetweenPixels() {
        JitteredSampler sampler = new JitteredSampler(16);
        double[] xs1 = samples(sampler, 10, 20, 7, true), ys1 = samples(sampler, 10, 20, 7, false);
        double[] xs2 = samples(sampler, 10, 20, 7, true), ys2 = samples(sampler, 10, 20, 7, false);

        assertArrayEquals(xs1, xs2, 0.0);
        assertArrayEquals(ys1, ys2, 0.0);
        assertFalse(Arrays.equals(xs1, samples(sampler, 11, 20, 7, true)), "neighbour in x");
        assertFalse(Arrays.equals(xs1, samples(sampler, 10, 21, 7, true)), "neighbour in y");
        assertFalse(Arrays.equals(xs1, samples(sampler, 20, 10, 7, true)), "transposed pixel");
        assertFalse(Arrays.equals(xs1, samples(sampler, 10, 20, 8, true)), "other seed");
    }

    private static double[] samples(Sampler sampler, int x, int y, long seed, boolean wantXs) {
        int n = sampler.samplesPerPixel();
        double[] xs = new double[n], ys = new double[n];
        PixelRandom random = new PixelRandom();
        random.nextDouble(); // state left over from an earlier pixel must not matter
        random.reset(x, y, seed);
        sampler.generate(random, xs, ys);
        return wantXs ? xs : ys;
    }

    @Test
    void pixelRandomIsUniformInTheHalfOpenUnitInterval() {
        PixelRandom random = new PixelRandom();
        int[] bins = new int[10];
        int n = 0;
        for (int pixel = 0; pixel < 1000; pixel++) {
            random.reset(pixel, -pixel, 99);
            for (int i = 0; i < 100; i++, n++) {
                double u = random.nextDouble();
                assertTrue(u >= 0 && u < 1, "value " + u);
                bins[(int) (u * 10)]++;
            }
        }
        for (int bin : bins) {
            assertEquals(n / 10.0, bin, 0.05 * n / 10, "bin counts " + Arrays.toString(bins));
        }
    }

    @Test
    void samplerByNameBuildsTheNamedKindAndRejectsUnknownNames() {
        assertInstanceOf(RegularSampler.class, Sampler.of("regular", 4));
        assertInstanceOf(JitteredSampler.class, Sampler.of("jittered", 6));
        assertThrows(IllegalArgumentException.class, () -> Sampler.of("sobol", 4));
        assertThrows(IllegalArgumentException.class, () -> new JitteredSampler(0));
    }
}

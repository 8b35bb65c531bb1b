package studio.engine.sampler;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

class SamplerTest {

    @Test
    void regularSamplerGivesTheCentresOfAKByKGrid() {
        for (int k = 1; k <= 5; k++) {
            int n = k * k;
            double[] xs = new double[n], ys = new double[n];

            Patterns.whole(new RegularSampler(n), new PixelRandom(), xs, ys);

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

        Patterns.whole(new RegularSampler(1), new PixelRandom(), xs, ys);

        assertEquals(0.5, xs[0], 0.0);
        assertEquals(0.5, ys[0], 0.0);
    }

    @Test
    void sobolSamplerWithOneSampleUsesThePixelCentreAndDrawsNothing() {
        double[] xs = new double[1], ys = new double[1];
        PixelRandom random = new PixelRandom();
        random.reset(5, 6, 7);

        Patterns.whole(new SobolSampler(1), random, xs, ys);

        assertEquals(0.5, xs[0], 0.0);
        assertEquals(0.5, ys[0], 0.0);
        assertEquals(0, new SobolSampler(1).draws(1));
        PixelRandom untouched = new PixelRandom();
        untouched.reset(5, 6, 7);
        assertEquals(untouched.nextInt(), random.nextInt(), "the pixel's stream is where it was");
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
            Patterns.whole(sampler, random, xs, ys);
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
        Patterns.whole(sampler, random, xs, ys);
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
        assertInstanceOf(RandomSampler.class, Sampler.of("random", 5));
        assertInstanceOf(JitteredSampler.class, Sampler.of("jittered", 6));
        assertInstanceOf(MultiJitteredSampler.class, Sampler.of("multijittered", 12));
        assertInstanceOf(SobolSampler.class, Sampler.of("sobol", 16));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Sampler.of("halton", 4));
        assertEquals("unknown sampler 'halton' (regular, random, jittered, multijittered, sobol)", e.getMessage());
        for (String name : Sampler.names()) {
            assertThrows(IllegalArgumentException.class, () -> Sampler.of(name, 0), name);
        }
    }

    @Test
    void samplerNamesAreListedSimplestFirstAndEachBuildsASamplerOfThatNameAndManySamples() {
        assertEquals(List.of("regular", "random", "jittered", "multijittered", "sobol"), Sampler.names());
        for (String name : Sampler.names()) {
            Sampler sampler = Sampler.of(name, 16);
            assertEquals(16, sampler.samplesPerPixel(), name);
            assertEquals(name, sampler.name());
        }
    }

    @Test
    void everySamplersOffsetsLieInTheHalfOpenUnitSquare() {
        PixelRandom random = new PixelRandom();
        for (String name : Sampler.names()) {
            for (int n : new int[] {1, 2, 3, 4, 5, 7, 9, 12, 16, 25, 32, 64, 100}) {
                if (name.equals("regular") && n != 1 && n != 4 && n != 9 && n != 16 && n != 25 && n != 64
                        && n != 100) {
                    continue;
                }
                Sampler sampler = Sampler.of(name, n);
                double[] xs = new double[n], ys = new double[n];
                for (int pixel = 0; pixel < 200; pixel++) {
                    random.reset(pixel, 3 * pixel, n);
                    Patterns.whole(sampler, random, xs, ys);
                    for (int i = 0; i < n; i++) {
                        assertTrue(xs[i] >= 0 && xs[i] < 1 && ys[i] >= 0 && ys[i] < 1,
                                name + " N=" + n + " sample " + i + ": " + xs[i] + ", " + ys[i]);
                    }
                }
            }
        }
    }

    @Test
    void everyRandomisedSamplerIsDeterministicPerPixelAndSeedAndDiffersBetweenPixels() {
        for (String name : List.of("random", "jittered", "multijittered", "sobol")) {
            Sampler sampler = Sampler.of(name, 16);
            double[] xs1 = samples(sampler, 10, 20, 7, true), ys1 = samples(sampler, 10, 20, 7, false);

            assertArrayEquals(xs1, samples(sampler, 10, 20, 7, true), 0.0, name);
            assertArrayEquals(ys1, samples(sampler, 10, 20, 7, false), 0.0, name);
            assertFalse(Arrays.equals(xs1, samples(sampler, 11, 20, 7, true)), name + ": neighbour in x");
            assertFalse(Arrays.equals(ys1, samples(sampler, 10, 21, 7, false)), name + ": neighbour in y");
            assertFalse(Arrays.equals(xs1, samples(sampler, 10, 20, 8, true)), name + ": other seed");
        }
    }

    @Test
    void consecutivePatternsFromOnePixelStreamDiffer() {
        // adaptive sampling draws one pattern per batch from the pixel's continuing stream
        for (String name : List.of("random", "jittered", "multijittered", "sobol")) {
            Sampler sampler = Sampler.of(name, 4);
            PixelRandom random = new PixelRandom();
            random.reset(5, 6, 7);
            double[] xs1 = new double[4], ys1 = new double[4], xs2 = new double[4], ys2 = new double[4];
            Patterns.whole(sampler, random, xs1, ys1);
            Patterns.whole(sampler, random, xs2, ys2);
            assertFalse(Arrays.equals(xs1, xs2) && Arrays.equals(ys1, ys2), name);
        }
    }

    @Test
    void multiJitteredSamplerHasOneSamplePerCellAndPerNarrowRowAndColumnIn1000Of1000Patterns() {
        // N = 16: a 4 x 4 grid and 16 narrow rows and columns (robustness case SAM-01); then other shapes of grid
        int[][] shapes = {{16, 4, 4}, {12, 3, 4}, {32, 4, 8}, {7, 1, 7}, {64, 8, 8}};
        PixelRandom random = new PixelRandom();
        for (int[] shape : shapes) {
            int n = shape[0], rows = shape[1], columns = shape[2];
            Sampler sampler = new MultiJitteredSampler(n);
            double[] xs = new double[n], ys = new double[n];
            int good = 0;
            for (int pixel = 0; pixel < 1000; pixel++) {
                random.reset(pixel % 41, pixel / 41, 2024);
                Patterns.whole(sampler, random, xs, ys);
                int[][] cells = new int[rows][columns];
                int[] narrowColumns = new int[n], narrowRows = new int[n];
                for (int i = 0; i < n; i++) {
                    cells[(int) (ys[i] * rows)][(int) (xs[i] * columns)]++;
                    narrowColumns[(int) (xs[i] * n)]++;
                    narrowRows[(int) (ys[i] * n)]++;
                }
                boolean ok = Arrays.stream(cells).flatMapToInt(Arrays::stream).allMatch(c -> c == 1)
                        && Arrays.stream(narrowColumns).allMatch(c -> c == 1)
                        && Arrays.stream(narrowRows).allMatch(c -> c == 1);
                good += ok ? 1 : 0;
            }
            assertEquals(1000, good, "patterns with the multi-jittered property, N=" + n);
        }
    }

    @Test
    void multiJitteredShufflesRemoveTheCanonicalDiagonal() {
        // canonical arrangement: x's narrow column within a cell column equals the cell row; shuffled, it varies
        Sampler sampler = new MultiJitteredSampler(16);
        PixelRandom random = new PixelRandom();
        double[] xs = new double[16], ys = new double[16];
        int canonical = 0;
        for (int pixel = 0; pixel < 100; pixel++) {
            random.reset(pixel, 0, 1);
            Patterns.whole(sampler, random, xs, ys);
            boolean diagonal = true;
            for (int s = 0; s < 16; s++) {
                int row = s / 4, narrow = (int) (xs[s] * 16) % 4;
                diagonal &= narrow == row;
            }
            canonical += diagonal ? 1 : 0;
        }
        assertTrue(canonical < 5, "unshuffled patterns: " + canonical);
    }

    @Test
    void sobolSecondDimensionFollowsItsDirectionNumbers() {
        // v = 1/2, 3/4, 5/8, 15/16 (m = 1, 3, 5, 15); point i is the XOR of v_k over the set bits k of i
        double[] expected = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875, 0.9375};
        for (int i = 0; i < expected.length; i++) {
            assertEquals(expected[i], (SobolSampler.sobolSecond(i) & 0xffffffffL) * 0x1.0p-32, 0.0, "point " + i);
        }
    }

    @Test
    void sobolSecondFromTablesEqualsTheBitLoop() {
        java.util.SplittableRandom random = new java.util.SplittableRandom(7);
        for (int k = 0; k < 100_000; k++) {
            int index = k < 1000 ? k : random.nextInt();
            assertEquals(Integer.reverse(SobolSampler.sobolSecond(index)), SobolSampler.sobolSecondReversed(index),
                    "index " + index);
        }
    }

    @Test
    void sobolSamplerIsAZeroMTwoNetForEveryPowerOfTwo() {
        PixelRandom random = new PixelRandom();
        for (int m = 0; m <= 8; m++) {
            int n = 1 << m;
            Sampler sampler = new SobolSampler(n);
            double[] xs = new double[n], ys = new double[n];
            for (int pixel = 0; pixel < (n <= 16 ? 1000 : 100); pixel++) {
                random.reset(pixel, m, 31);
                Patterns.whole(sampler, random, xs, ys);
                for (int a = 0; a <= m; a++) {
                    // elementary intervals of 2^a columns by 2^(m - a) rows: exactly one point each
                    int columns = 1 << a, rows = 1 << (m - a);
                    boolean[] seen = new boolean[n];
                    for (int i = 0; i < n; i++) {
                        int cell = (int) (ys[i] * rows) * columns + (int) (xs[i] * columns);
                        assertFalse(seen[cell], "N=" + n + " pixel " + pixel + ": two points in an interval of "
                                + columns + " x " + rows);
                        seen[cell] = true;
                    }
                }
            }
        }
    }

    @Test
    void sobolPointIsBothDimensionsOwenScrambledAtTheScrambledIndex() {
        // point i: the index Owen-scrambled, then van der Corput's and Sobol's second dimension of it,
        // each Owen-scrambled with its own seed; past the table of the first indices' reversals too
        Random cases = new Random(11);
        double[] xs = new double[1024], ys = new double[1024];
        for (int t = 0; t < 20; t++) {
            int indexSeed = cases.nextInt(), xSeed = cases.nextInt(), ySeed = cases.nextInt();
            SobolSampler.points(indexSeed, xSeed, ySeed, 0, 1024, xs, ys);
            for (int i = 0; i < 1024; i++) {
                int index = SobolSampler.owenScramble(i, indexSeed);
                int x = SobolSampler.owenScramble(Integer.reverse(index), xSeed);
                int y = SobolSampler.owenScramble(SobolSampler.sobolSecond(index), ySeed);
                assertEquals((x & 0xffffffffL) * 0x1.0p-32, xs[i], 0.0, "x of point " + i);
                assertEquals((y & 0xffffffffL) * 0x1.0p-32, ys[i], 0.0, "y of point " + i);
            }
        }
    }

    @Test
    void owenScramblingKeepsEachBitsPrefixTogether() {
        // points that share their top k bits still share them (possibly flipped) after scrambling
        Random cases = new Random(5);
        for (int t = 0; t < 10_000; t++) {
            int seed = cases.nextInt(), a = cases.nextInt(), k = 1 + cases.nextInt(31);
            int b = a ^ (cases.nextInt() >>> k); // same top k bits as a
            int sa = SobolSampler.owenScramble(a, seed), sb = SobolSampler.owenScramble(b, seed);
            assertEquals(sa >>> (32 - k), sb >>> (32 - k), "prefix of " + k + " bits");
        }
    }

    @Test
    void pixelRandomBoundedIntsAreInRangeAndUniform() {
        PixelRandom random = new PixelRandom();
        random.reset(1, 2, 3);
        int[] counts = new int[7];
        for (int i = 0; i < 70_000; i++) {
            int k = random.nextInt(7);
            assertTrue(k >= 0 && k < 7, "value " + k);
            counts[k]++;
        }
        for (int c : counts) {
            assertEquals(10_000, c, 400, Arrays.toString(counts));
        }
        assertEquals(0, random.nextInt(1));
    }
}

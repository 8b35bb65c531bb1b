package studio.engine.sampler;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.Arrays;
import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * A pixel's samples by index are the patterns a pixel's random stream gives when they are drawn one
 * after the other, whatever runs are asked for and in whatever order.
 */
class PixelSamplesTest {

    private static final long SEED = 42;

    /** The samplers with N samples (regular only for square N) and the pattern sizes to cut them into. */
    private static final int[] COUNTS = {1, 3, 4, 9, 12, 16, 18, 64};

    private static boolean square(int n) {
        int k = (int) Math.round(Math.sqrt(n));
        return k * k == n;
    }

    @Test
    void aPatternDrawsAsManyValuesAsTheSamplerSays() {
        PixelRandom drawn = new PixelRandom(), skipped = new PixelRandom();
        for (String name : Sampler.names()) {
            for (int n : COUNTS) {
                if (name.equals("regular") && !square(n)) {
                    continue;
                }
                Sampler sampler = Sampler.of(name, n);
                double[] xs = new double[n], ys = new double[n];
                for (int pixel = 0; pixel < 20; pixel++) {
                    drawn.reset(pixel, 7, SEED);
                    Patterns.whole(sampler, drawn, xs, ys);
                    skipped.reset(pixel, 7, SEED);
                    skipped.skip(sampler.draws(n));
                    assertEquals(skipped.nextDouble(), drawn.nextDouble(), 0.0, name + " N=" + n);
                }
            }
        }
    }

    @Test
    void sampleIsElementOfItsPatternDrawnAfterThePatternsBeforeIt() {
        for (String name : Sampler.names()) {
            for (int n : COUNTS) {
                for (int patternSize : new int[] {n, 4, 1}) {
                    if (name.equals("regular") && (!square(n) || patternSize != n)) {
                        continue;
                    }
                    Sampler sampler = Sampler.of(name, n);
                    PixelSamples samples = new PixelSamples(sampler, patternSize, SEED);
                    double[] xs = new double[n], ys = new double[n];
                    double[] expectedXs = new double[n], expectedYs = new double[n];
                    for (int pixel = 0; pixel < 10; pixel++) {
                        patternsOneAfterAnother(sampler, Math.min(patternSize, n), pixel, expectedXs, expectedYs);
                        samples.startPixel(pixel, 3);
                        samples.fill(0, n, xs, ys);
                        String what = name + " N=" + n + " patterns of " + patternSize;
                        assertArrayEquals(expectedXs, xs, 0.0, what);
                        assertArrayEquals(expectedYs, ys, 0.0, what);
                    }
                }
            }
        }
    }

    /** The pixel's samples as drawing whole patterns from one continuing stream gives them. */
    private static void patternsOneAfterAnother(Sampler sampler, int size, int pixel, double[] xs, double[] ys) {
        PixelRandom random = new PixelRandom();
        random.reset(pixel, 3, SEED);
        int n = sampler.samplesPerPixel();
        double[] px = new double[size], py = new double[size];
        for (int start = 0; start < n; start += size) {
            int count = Math.min(size, n - start);
            sampler.fill(random, count, 0, count, px, py);
            System.arraycopy(px, 0, xs, start, count);
            System.arraycopy(py, 0, ys, start, count);
        }
    }

    @Test
    void anyRunsInAnyOrderGiveTheSameSamples() {
        Random order = new Random(1);
        for (String name : Sampler.names()) {
            int n = name.equals("regular") ? 16 : 18;
            for (int patternSize : new int[] {n, 4}) {
                if (name.equals("regular") && patternSize != n) {
                    continue;
                }
                PixelSamples samples = new PixelSamples(Sampler.of(name, n), patternSize, SEED);
                double[] wholeXs = new double[n], wholeYs = new double[n], xs = new double[n], ys = new double[n];
                samples.startPixel(5, 6);
                samples.fill(0, n, wholeXs, wholeYs);
                for (int trial = 0; trial < 20; trial++) {
                    Arrays.fill(xs, -1);
                    Arrays.fill(ys, -1);
                    samples.startPixel(order.nextInt(4), 9); // another pixel in between changes nothing
                    samples.fill(0, 1 + order.nextInt(n), new double[n], new double[n]);
                    samples.startPixel(5, 6);
                    // random runs, last run first, until every sample is filled
                    for (int end = n; end > 0; ) {
                        int first = order.nextInt(end);
                        samples.fill(first, end - first, xs, ys);
                        end = first;
                    }
                    assertArrayEquals(wholeXs, xs, 0.0, name + " patterns of " + patternSize);
                    assertArrayEquals(wholeYs, ys, 0.0, name + " patterns of " + patternSize);
                }
            }
        }
    }

    @Test
    void rejectsSamplesOutsideThePixels() {
        PixelSamples samples = new PixelSamples(new JitteredSampler(8), 4, SEED);
        double[] xs = new double[9], ys = new double[9];
        assertThrows(IndexOutOfBoundsException.class, () -> samples.fill(4, 5, xs, ys));
        assertThrows(IndexOutOfBoundsException.class, () -> samples.fill(-1, 2, xs, ys));
        assertThrows(IllegalArgumentException.class, () -> new PixelSamples(new JitteredSampler(8), 0, SEED));
    }

    @Test
    void fillingSamplesAllocatesNothing() {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long thread = Thread.currentThread().getId();
        for (String name : Sampler.names()) {
            PixelSamples samples = new PixelSamples(Sampler.of(name, 16), name.equals("regular") ? 16 : 4, SEED);
            double[] xs = new double[16], ys = new double[16];
            double[] sink = new double[1];
            fillPixels(samples, xs, ys, sink); // warm-up: lets the JIT compile the loop
            long before = threads.getThreadAllocatedBytes(thread);
            fillPixels(samples, xs, ys, sink);
            long bytes = threads.getThreadAllocatedBytes(thread) - before;
            assertTrue(bytes < 4096, name + ": allocated " + bytes + " bytes for 10^5 pixels");
            assertTrue(Double.isFinite(sink[0]));
        }
    }

    private static void fillPixels(PixelSamples samples, double[] xs, double[] ys, double[] sink) {
        double sum = 0;
        for (int pixel = 0; pixel < 100_000; pixel++) {
            samples.startPixel(pixel % 317, pixel / 317);
            samples.fill(0, 4, xs, ys);
            samples.fill(4, 12, xs, ys);
            sum += xs[0] + ys[15];
        }
        sink[0] += sum;
    }
}

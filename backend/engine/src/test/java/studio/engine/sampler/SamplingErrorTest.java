package studio.engine.sampler;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Robustness case SAM-01 and SAM-02, at the sampler level: the error of a pixel's estimate of a known coverage.
 * Regular grids alias on stripes finer than the grid (documented); the random samplers do not. On edges the
 * error of stratified samplers (jittered, multi-jittered, Sobol) falls like N^-3/4, of random ones like N^-1/2.
 */
class SamplingErrorTest {

    private static final int SIZE = 128;
    private static final int[] COUNTS = {4, 16, 64, 256, 1024};

    @ParameterizedTest
    @ValueSource(strings = {"random", "jittered", "multijittered", "sobol"})
    void randomisedSamplersDoNotAliasOnFineStripes(String name) {
        for (double period : new double[] {0.26, 0.2502}) {
            double rms = stripeBlockErrorRms(Sampler.of(name, 16), period);
            assertTrue(rms <= 0.03, name + " 8x8 block-mean error RMS " + rms + " at period " + period);
        }
    }

    @Test
    void regularGridAliasesOnStripesNearItsOwnPeriod() {
        // documented behaviour: with period 0.2502 px every 4x4 sample falls on the same phase of the stripes
        double rms = stripeBlockErrorRms(new RegularSampler(16), 0.2502);
        assertTrue(rms > 0.4, "regular 8x8 block-mean error RMS " + rms);
    }

    @Test
    void regularGridShowsMoireBandsOnStripesOfPeriod026() {
        // documented behaviour: slow beats between the grid and the stripes (robustness case SAM-01 measured 0.077)
        double rms = stripeBlockErrorRms(new RegularSampler(16), 0.26);
        assertTrue(rms > 0.03, "regular 8x8 block-mean error RMS " + rms);
    }

    /** Stripes f = [frac(x / period) < 1/2], x in pixels; RMS over 8x8 blocks of the mean per-pixel error. */
    private static double stripeBlockErrorRms(Sampler sampler, double period) {
        int n = sampler.samplesPerPixel();
        double[] xs = new double[n], ys = new double[n];
        PixelRandom random = new PixelRandom();
        double[][] blockError = new double[SIZE / 8][SIZE / 8];
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                random.reset(x, y, 2024);
                Patterns.whole(sampler, random, xs, ys);
                double estimate = 0;
                for (int s = 0; s < n; s++) {
                    double phase = (x + xs[s]) / period;
                    estimate += phase - Math.floor(phase) < 0.5 ? 1 : 0;
                }
                estimate /= n;
                double exact = stripeIntegral(x + 1, period) - stripeIntegral(x, period);
                blockError[y / 8][x / 8] += (estimate - exact) / 64;
            }
        }
        double sum = 0;
        for (double[] row : blockError) {
            for (double e : row) {
                sum += e * e;
            }
        }
        return Math.sqrt(sum / (SIZE / 8 * SIZE / 8));
    }

    /** The integral of the stripe pattern from 0 to x. */
    private static double stripeIntegral(double x, double period) {
        double cycles = Math.floor(x / period);
        return period * (cycles * 0.5 + Math.min(x / period - cycles, 0.5));
    }

    @ParameterizedTest
    @ValueSource(strings = {"jittered", "multijittered", "sobol"})
    void stratifiedErrorOnEdgesFallsLikeNToTheMinusThreeQuarters(String name) {
        double slope = slope(edgeErrorRms(name));
        assertTrue(slope <= -0.65, name + ": log-log slope of the RMS error: " + slope);
    }

    @Test
    void randomErrorOnEdgesFallsLikeOneOverSquareRootN() {
        double slope = slope(edgeErrorRms("random"));
        assertTrue(slope >= -0.55 && slope <= -0.45, "random: log-log slope of the RMS error: " + slope);
    }

    @Test
    void jitteredErrorOnEdgesAt64SamplesIsAtMostHalfOfRandom() {
        double jittered = edgeErrorRms("jittered")[2], random = edgeErrorRms("random")[2];
        assertTrue(jittered <= 0.5 * random, "RMS at N=64: jittered " + jittered + ", random " + random);
    }

    /** RMS coverage error over 4000 random straight edges through a pixel, for each N of {@link #COUNTS}. */
    private static double[] edgeErrorRms(String name) {
        Random edges = new Random(99);
        int edgeCount = 4000;
        double[][] edge = new double[edgeCount][3];
        for (double[] e : edge) {
            double angle = 2 * Math.PI * edges.nextDouble();
            e[0] = Math.cos(angle);
            e[1] = Math.sin(angle);
            e[2] = -0.35 + 0.7 * edges.nextDouble();
        }
        double[] rms = new double[COUNTS.length];
        PixelRandom random = new PixelRandom();
        for (int k = 0; k < COUNTS.length; k++) {
            int n = COUNTS[k];
            Sampler sampler = Sampler.of(name, n);
            double[] xs = new double[n], ys = new double[n];
            double sum = 0;
            for (int i = 0; i < edgeCount; i++) {
                random.reset(i, n, 7);
                Patterns.whole(sampler, random, xs, ys);
                int inside = 0;
                for (int s = 0; s < n; s++) {
                    inside += (xs[s] - 0.5) * edge[i][0] + (ys[s] - 0.5) * edge[i][1] < edge[i][2] ? 1 : 0;
                }
                double error = (double) inside / n - coverage(edge[i][0], edge[i][1], edge[i][2]);
                sum += error * error;
            }
            rms[k] = Math.sqrt(sum / edgeCount);
        }
        return rms;
    }

    /** Area of {p in [0,1]^2 : (p - (1/2, 1/2)) . (nx, ny) < offset}, by clipping the square (Sutherland-Hodgman). */
    private static double coverage(double nx, double ny, double offset) {
        double[][] square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        double[][] clipped = new double[8][];
        int m = 0;
        for (int i = 0; i < 4; i++) {
            double[] a = square[i], b = square[(i + 1) % 4];
            double da = (a[0] - 0.5) * nx + (a[1] - 0.5) * ny - offset;
            double db = (b[0] - 0.5) * nx + (b[1] - 0.5) * ny - offset;
            if (da < 0) {
                clipped[m++] = a;
            }
            if (da < 0 != db < 0) {
                double t = da / (da - db);
                clipped[m++] = new double[] {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
            }
        }
        double area = 0;
        for (int i = 0; i < m; i++) {
            double[] a = clipped[i], b = clipped[(i + 1) % m];
            area += a[0] * b[1] - b[0] * a[1];
        }
        return Math.abs(area) / 2;
    }

    /** The least-squares slope of log(rms) against log(N). */
    private static double slope(double[] rms) {
        double[] x = new double[COUNTS.length], y = new double[COUNTS.length];
        for (int k = 0; k < COUNTS.length; k++) {
            x[k] = Math.log(COUNTS[k]);
            y[k] = Math.log(rms[k]);
        }
        double mx = 0, my = 0;
        for (int i = 0; i < x.length; i++) {
            mx += x[i] / x.length;
            my += y[i] / y.length;
        }
        double sxy = 0, sxx = 0;
        for (int i = 0; i < x.length; i++) {
            sxy += (x[i] - mx) * (y[i] - my);
            sxx += (x[i] - mx) * (x[i] - mx);
        }
        return sxy / sxx;
    }
}

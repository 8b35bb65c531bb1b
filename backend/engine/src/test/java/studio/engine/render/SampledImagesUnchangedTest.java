package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.stream.Stream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import studio.engine.sampler.Sampler;
import studio.engine.scene.Scene;

/**
 * Every sampler under every sampling strategy puts its samples where it always has: small renders
 * of glass, a mirror and a box's edges come out bit for bit as recorded. Reference renders, the
 * live view's final frame (equal to a plain render's) and a cluster's images assembled from several
 * machines all depend on a pixel's samples never moving. The fingerprints were recorded from the
 * renderer before samplers had index access (when a pixel drew whole patterns from its random
 * stream: one of N, or under batch-adaptive sampling one of 4 per batch, and progressive sobol
 * walked one sequence a run at a time), and recorded again when weak branches at glass began to
 * play a roulette ({@link BranchRoulette}), whose draws are as fixed as the samples, and again when
 * a light too faint to show stopped being looked for ({@link Integrator#NEGLIGIBLE_LIGHT}: the same
 * samples taken, values within a millionth). Change them
 * only with a deliberate change of the samples or of how a sample is traced.
 */
class SampledImagesUnchangedTest {

    private static final Scene SCENE = MixedScene.SCENE;
    /** 24 x 16 cuts into tiles of 16 on one thread: two tiles, so progressive sobol shares a border. */
    private static final int WIDTH = 24, HEIGHT = 16;

    /** sampler, samples per pixel (the maximum, if adaptive), adaptive threshold, fingerprint, samples taken. */
    static Stream<Arguments> renders() {
        return Stream.of(
                // fixed: one pattern of N per pixel
                Arguments.of("regular", 9, 0.0, "9ff175ae4ab94688", 3456L),
                Arguments.of("random", 16, 0.0, "230b234b8a088162", 6144L),
                Arguments.of("jittered", 16, 0.0, "2cb3d44ddaa2d3a8", 6144L),
                Arguments.of("multijittered", 16, 0.0, "879804e0e60408ea", 6144L),
                Arguments.of("multijittered", 12, 0.0, "484faf9aa2114d62", 4608L),
                Arguments.of("sobol", 16, 0.0, "cecb4c829bf6d0f8", 6144L),
                // batch-adaptive: patterns of 4, the last partial when N is not a multiple of 4
                Arguments.of("random", 16, 0.05, "c4c2705e44e87c30", 3656L),
                Arguments.of("jittered", 16, 0.05, "ace9df5cb1819fc6", 3644L),
                Arguments.of("multijittered", 16, 0.05, "e013fd89064e458d", 3632L),
                Arguments.of("random", 9, 0.05, "1b753457791c7fd7", 3152L),
                Arguments.of("jittered", 9, 0.05, "daeebfac85341865", 3151L),
                Arguments.of("multijittered", 9, 0.05, "ad766cc620e321a7", 3150L),
                Arguments.of("multijittered", 18, 0.05, "b12dcd8d6969b3b1", 3692L),
                // progressive sobol: one sequence, 1 base sample, then 4, then doubling; a maximum that is not a
                // power of two ends on a partial run (recorded again when the base went from 4 samples to 1)
                Arguments.of("sobol", 16, 0.05, "db6fb36b80079bf0", 3167L),
                Arguments.of("sobol", 9, 0.05, "a8c309aedf10c6ea", 2600L),
                Arguments.of("sobol", 64, 0.05, "c8cc56ba8014c96f", 3871L));
    }

    @ParameterizedTest(name = "{0} {1} adaptive {2}")
    @MethodSource("renders")
    void rendersTheRecordedImage(String sampler, int samples, double threshold, String fingerprint, long taken) {
        RenderSettings settings = new RenderSettings(WIDTH, HEIGHT, Sampler.of(sampler, samples), 6, 1, 42L,
                RenderSettings.DEFAULT_MIN_PATH_WEIGHT, threshold);
        RenderResult result = Renderer.render(RenderRequest.of(SCENE, settings));

        long pixels = (long) WIDTH * HEIGHT;
        if (threshold > 0) { // the strategy's decisions are exercised: some pixels stop early, some go on
            int fewest = sampler.equals("sobol") ? ProgressiveSobolSampling.BASE : Math.min(samples, 4);
            assertTrue(result.samplesTaken() > pixels * fewest && result.samplesTaken() < pixels * samples,
                    "samples taken: " + result.samplesTaken());
        }
        assertEquals(fingerprint + " " + taken, fingerprint(result.film()) + " " + result.samplesTaken(),
                "fingerprint and samples of " + sampler + " " + samples + " adaptive " + threshold);
    }

    /** FNV-1a over every bit of every channel of every pixel, row by row. */
    static String fingerprint(Film film) {
        long hash = 0xcbf29ce484222325L;
        for (int y = 0; y < film.height(); y++) {
            for (int x = 0; x < film.width(); x++) {
                for (int c = 0; c < 3; c++) {
                    long bits = Double.doubleToRawLongBits(film.get(x, y, c));
                    for (int b = 0; b < 64; b += 8) {
                        hash = (hash ^ ((bits >>> b) & 0xff)) * 0x100000001b3L;
                    }
                }
            }
        }
        return String.format("%016x", hash);
    }
}

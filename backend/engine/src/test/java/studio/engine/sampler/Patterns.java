package studio.engine.sampler;

/** Test helper: a sampler's patterns as a pixel under fixed sampling takes them. */
final class Patterns {

    private Patterns() {
    }

    /** One whole pattern of the sampler's samples per pixel, drawn from random's current position. */
    static void whole(Sampler sampler, PixelRandom random, double[] xs, double[] ys) {
        int n = sampler.samplesPerPixel();
        sampler.fill(random, n, 0, n, xs, ys);
    }
}

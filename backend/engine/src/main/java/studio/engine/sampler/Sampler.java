package studio.engine.sampler;

import java.util.List;

/**
 * Where in a pixel the samples go: offsets in [0, 1)^2 from the pixel's top-left corner. A sampler
 * makes patterns: a pattern of n samples is stratified as a whole (for jittered, its n cells), and
 * draws a fixed number of values, {@link #draws(int)}, from the {@link PixelRandom} it is given.
 * A render asks for a pixel's samples by index through {@link PixelSamples}, which knows where in
 * the pixel's random stream each pattern starts; so a pixel's samples do not depend on threads, on
 * the order of pixels or on which of them were asked for before.
 */
public sealed interface Sampler
        permits RegularSampler, RandomSampler, JitteredSampler, MultiJitteredSampler, SobolSampler {

    /** The samples a pixel takes (with adaptive sampling, the most it may take). */
    int samplesPerPixel();

    /** This sampler's name in the scene format (one of {@link #names()}). */
    String name();

    /** How many values of the random stream one pattern of {@code size} samples draws. */
    int draws(int size);

    /**
     * Samples first .. first + count - 1 of a pattern of {@code size} samples into xs and ys at the
     * same indices. {@code random} stands at the pattern's first draw; a whole pattern leaves it
     * just after the pattern's {@link #draws} values. The multi-jittered sampler fills the whole
     * pattern (its shuffles tie the samples together), so xs and ys hold at least {@code size}; the
     * others fill only the samples asked for.
     */
    void fill(PixelRandom random, int size, int first, int count, double[] xs, double[] ys);

    /** The scene-format names of the samplers, in a stable order: simplest first. */
    static List<String> names() {
        return List.of("regular", "random", "jittered", "multijittered", "sobol");
    }

    /** The sampler called {@code name} in the scene format (one of {@link #names()}). */
    static Sampler of(String name, int samplesPerPixel) {
        return switch (name) {
            case "regular" -> new RegularSampler(samplesPerPixel);
            case "random" -> new RandomSampler(samplesPerPixel);
            case "jittered" -> new JitteredSampler(samplesPerPixel);
            case "multijittered" -> new MultiJitteredSampler(samplesPerPixel);
            case "sobol" -> new SobolSampler(samplesPerPixel);
            default -> throw new IllegalArgumentException("unknown sampler '" + name + "' ("
                    + String.join(", ", names()) + ")");
        };
    }
}

package studio.engine.sampler;

import java.util.List;

/**
 * Where in a pixel the samples go: offsets in [0, 1)^2 from the pixel's top-left corner. Every
 * sampler draws its randomness only from the {@link PixelRandom} it is given, which the renderer
 * resets per pixel, so a pixel's samples do not depend on threads or on the order of pixels.
 */
public sealed interface Sampler
        permits RegularSampler, RandomSampler, JitteredSampler, MultiJitteredSampler, SobolSampler {

    int samplesPerPixel();

    /** Fills {@code xs} and {@code ys} (length at least samplesPerPixel) with this pixel's offsets. */
    void generate(PixelRandom random, double[] xs, double[] ys);

    /** The same kind of sampler with another number of samples per pixel (e.g. one batch of adaptive sampling). */
    Sampler withSamplesPerPixel(int samplesPerPixel);

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

package studio.engine.sampler;

/** Where in a pixel the samples go: offsets in [0, 1)^2 from the pixel's top-left corner. */
public sealed interface Sampler permits RegularSampler, JitteredSampler {

    int samplesPerPixel();

    /** Fills {@code xs} and {@code ys} (length at least samplesPerPixel) with this pixel's offsets. */
    void generate(PixelRandom random, double[] xs, double[] ys);

    /** The sampler called {@code name} in the scene format ("regular" or "jittered"). */
    static Sampler of(String name, int samplesPerPixel) {
        return switch (name) {
            case "regular" -> new RegularSampler(samplesPerPixel);
            case "jittered" -> new JitteredSampler(samplesPerPixel);
            default -> throw new IllegalArgumentException("unknown sampler '" + name + "' (regular, jittered)");
        };
    }
}

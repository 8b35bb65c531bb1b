package studio.bench.accuracy;

/**
 * One way of spending samples: a sampler at a fixed count per pixel, or adaptive sampling on top
 * of a sampler, stopping each pixel at a threshold.
 *
 * @param name              as it appears in the CSV, the chart and the summary
 * @param sampler           the engine's sampler name
 * @param adaptiveThreshold NaN for a fixed count
 */
record Method(String name, String sampler, double adaptiveThreshold) {

    static Method fixed(String sampler) {
        return new Method(sampler, sampler, Double.NaN);
    }

    static Method adaptive(String sampler, double threshold) {
        return new Method("adaptive-" + sampler, sampler, threshold);
    }

    /**
     * Adaptive sampling at one threshold with the most samples a pixel may take varied: the curve a
     * user walks along by changing only {@code render.samples} of a scene with the default sampling.
     */
    static Method adaptiveBySamples(String sampler, double threshold) {
        return new Method(BY_SAMPLES_PREFIX + sampler + BY_SAMPLES_SUFFIX, sampler, threshold);
    }

    static final String BY_SAMPLES_PREFIX = "adaptive-", BY_SAMPLES_SUFFIX = "-samples";

    /** Whether this is a curve of {@link #adaptiveBySamples}, by its name. */
    static boolean isBySamples(String name) {
        return name.startsWith(BY_SAMPLES_PREFIX) && name.endsWith(BY_SAMPLES_SUFFIX);
    }

    boolean isAdaptive() {
        return !Double.isNaN(adaptiveThreshold);
    }
}

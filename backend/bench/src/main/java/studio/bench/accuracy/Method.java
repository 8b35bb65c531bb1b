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

    boolean isAdaptive() {
        return !Double.isNaN(adaptiveThreshold);
    }
}

package studio.engine.render;

import studio.engine.sampler.RegularSampler;
import studio.engine.sampler.Sampler;

/**
 * How to render: image size, where samples go, recursion depth, threads and seed.
 *
 * @param sampler            where a pixel's samples go; its samplesPerPixel is the number of samples
 *                           per pixel, or with adaptive sampling the most a pixel may take
 * @param threads            worker threads; 0 means one per available core
 * @param minPathWeight      a reflected or refracted ray whose throughput (the fraction of its
 *                           radiance that reaches its sample) is below this is not traced: it could
 *                           not change an 8-bit pixel even as the pixel's only sample; 0 traces all
 * @param adaptiveThreshold  0: every pixel takes all its samples. Above 0: adaptive sampling with this
 *                           relative error threshold (see {@link Renderer} for the exact stopping rule)
 */
public record RenderSettings(int width, int height, Sampler sampler, int maxDepth, int threads, long seed,
                             double minPathWeight, double adaptiveThreshold) {

    /** Half of one 8-bit step in linear light near black: below it a path cannot change a pixel. */
    public static final double DEFAULT_MIN_PATH_WEIGHT = 1.0 / 1024;
    public static final int TILE_SIZE = 32;

    public RenderSettings {
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("image size must be at least 1x1: " + width + "x" + height);
        }
        if (sampler == null) {
            throw new IllegalArgumentException("a sampler is required");
        }
        if (maxDepth < 0) {
            throw new IllegalArgumentException("maxDepth must not be negative: " + maxDepth);
        }
        if (threads < 0) {
            throw new IllegalArgumentException("threads must not be negative: " + threads);
        }
        if (!(minPathWeight >= 0)) {
            throw new IllegalArgumentException("minPathWeight must not be negative: " + minPathWeight);
        }
        if (!(adaptiveThreshold >= 0) || adaptiveThreshold == Double.POSITIVE_INFINITY) {
            throw new IllegalArgumentException("adaptiveThreshold must be finite and not negative: "
                    + adaptiveThreshold);
        }
        if (adaptiveThreshold > 0 && sampler instanceof RegularSampler) {
            throw new IllegalArgumentException("adaptive sampling needs a random sampler: the regular sampler "
                    + "would put every batch on the same grid");
        }
    }

    /** Without adaptive sampling. */
    public RenderSettings(int width, int height, Sampler sampler, int maxDepth, int threads, long seed,
                          double minPathWeight) {
        this(width, height, sampler, maxDepth, threads, seed, minPathWeight, 0);
    }

    public RenderSettings(int width, int height, Sampler sampler, int maxDepth, int threads) {
        this(width, height, sampler, maxDepth, threads, 0L, DEFAULT_MIN_PATH_WEIGHT);
    }

    /**
     * Whether pixels stop taking samples once their estimate is good enough: with a threshold, and
     * more than one sample a pixel to stop within (with one, every pixel takes it, as without).
     */
    public boolean adaptive() {
        return adaptiveThreshold > 0 && sampler.samplesPerPixel() > 1;
    }

    /** Camera samples the render takes at most: width x height x samples a pixel (fewer where adaptive sampling stops early). */
    public long cameraSamples() {
        return (long) width * height * sampler.samplesPerPixel();
    }

    /** The number of worker threads this render will use. */
    public int effectiveThreads() {
        return threads > 0 ? threads : Runtime.getRuntime().availableProcessors();
    }

    public RenderSettings withThreads(int newThreads) {
        return new RenderSettings(width, height, sampler, maxDepth, newThreads, seed, minPathWeight,
                adaptiveThreshold);
    }

    public RenderSettings withAdaptiveThreshold(double threshold) {
        return new RenderSettings(width, height, sampler, maxDepth, threads, seed, minPathWeight, threshold);
    }
}

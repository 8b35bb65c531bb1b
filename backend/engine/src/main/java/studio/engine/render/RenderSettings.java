package studio.engine.render;

import studio.engine.sampler.Sampler;

/**
 * How to render: image size, where samples go, recursion depth, threads and seed.
 *
 * @param threads        worker threads; 0 means one per available core
 * @param minPathWeight  a reflected or refracted ray whose contribution to the pixel would be
 *                       below this is not traced (it cannot change an 8-bit pixel); 0 traces all
 */
public record RenderSettings(int width, int height, Sampler sampler, int maxDepth, int threads, long seed,
                             double minPathWeight) {

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
    }

    public RenderSettings(int width, int height, Sampler sampler, int maxDepth, int threads) {
        this(width, height, sampler, maxDepth, threads, 0L, DEFAULT_MIN_PATH_WEIGHT);
    }

    /** The number of worker threads this render will use. */
    public int effectiveThreads() {
        return threads > 0 ? threads : Runtime.getRuntime().availableProcessors();
    }

    public RenderSettings withThreads(int newThreads) {
        return new RenderSettings(width, height, sampler, maxDepth, newThreads, seed, minPathWeight);
    }
}

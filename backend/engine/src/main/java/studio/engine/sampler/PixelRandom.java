package studio.engine.sampler;

/**
 * A small, fast random generator (SplitMix64) seeded from a pixel and the scene's seed, so each
 * pixel draws the same numbers whatever thread renders it and in whatever order.
 */
public final class PixelRandom {

    private long state;

    public PixelRandom() {
    }

    /** Restarts the sequence for pixel (x, y) of a render with the given seed. */
    public void reset(int x, int y, long seed) {
        state = mix(seed ^ mix(((long) x << 32) ^ (y & 0xffffffffL) ^ 0x5851f42d4c957f2dL));
    }

    /** A uniform double in [0, 1). */
    public double nextDouble() {
        return (next() >>> 11) * 0x1.0p-53;
    }

    /** 32 uniform random bits (for scrambling seeds). */
    public int nextInt() {
        return (int) (next() >>> 32);
    }

    /** A uniform int in [0, bound), bound at least 1 (Lemire's multiply-shift; bias below 2^-32 * bound). */
    public int nextInt(int bound) {
        return (int) (((next() >>> 32) * bound) >>> 32);
    }

    private long next() {
        state += 0x9e3779b97f4a7c15L;
        return mix(state);
    }

    private static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xbf58476d1ce4e5b9L;
        z = (z ^ (z >>> 27)) * 0x94d049bb133111ebL;
        return z ^ (z >>> 31);
    }
}

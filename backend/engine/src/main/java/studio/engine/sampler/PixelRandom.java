package studio.engine.sampler;

/**
 * A small, fast random generator (SplitMix64) seeded from a pixel and the scene's seed, so each
 * pixel draws the same numbers whatever thread renders it and in whatever order. Its state only
 * counts (by a fixed odd step) and each number is a hash of the count, so it can {@link #skip}
 * ahead to any position of its stream at once: a pixel's k-th pattern is drawn from where the
 * patterns before it would have left the stream, without drawing them.
 */
public final class PixelRandom {

    /** The step of the state per number drawn (odd, so the state runs through every 64-bit value). */
    private static final long GAMMA = 0x9e3779b97f4a7c15L;

    private long state;

    public PixelRandom() {
    }

    /** Restarts the sequence for pixel (x, y) of a render with the given seed. */
    public void reset(int x, int y, long seed) {
        state = mix(seed ^ mix(((long) x << 32) ^ (y & 0xffffffffL) ^ 0x5851f42d4c957f2dL));
    }

    /** Moves on {@code count} numbers without drawing them: the next number is the one after them. */
    public void skip(long count) {
        state += count * GAMMA;
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
        state += GAMMA;
        return mix(state);
    }

    private static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xbf58476d1ce4e5b9L;
        z = (z ^ (z >>> 27)) * 0x94d049bb133111ebL;
        return z ^ (z >>> 31);
    }
}

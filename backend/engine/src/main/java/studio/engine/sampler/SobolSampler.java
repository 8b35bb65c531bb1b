package studio.engine.sampler;

/**
 * The first two dimensions of the Sobol sequence (van der Corput in base 2 for x, Sobol's second
 * dimension for y) with Owen scrambling, seeded per pixel: a randomised (0, 2)-sequence.
 *
 * <p>Scrambling follows Burley, "Practical Hash-based Owen Scrambling" (JCGT 9(4), 2020): the
 * point index is shuffled by a nested uniform scramble and each coordinate gets its own nested
 * uniform (Owen) scramble, all built on a Laine-Karras style hash (the improved constants of
 * N. Vegdahl, "Building a Better LK Hash", 2021). The three 32-bit seeds are drawn from the pixel's
 * random stream where the pattern starts, so every pattern, e.g. every batch of adaptive sampling,
 * is a fresh, independent one; and any run of a pattern's points costs only those points
 * (progressive sampling walks a pixel's one pattern a run at a time). Whenever N is a power of two
 * the N points are a (0, m, 2)-net: every elementary interval of area 1/N (1/N x 1, 2/N x 1/2, ...,
 * 1 x 1/N) holds exactly one point, so the pattern is stratified in every aspect ratio at once.
 * Other N take the first N points of such a net.
 *
 * <p>One point alone is the pixel's centre, drawing nothing: any single point is a net, and the
 * centre is the best one for a pixel whose colour varies smoothly (the midpoint rule's error falls
 * with the square of the pixel's size, a random point's only with its size): a third less RMSE than
 * a random point on each of the speed-accuracy bench's four scenes at one sample a pixel.
 */
public record SobolSampler(int samplesPerPixel) implements Sampler {

    public SobolSampler {
        Strata.requirePositive(samplesPerPixel);
    }

    @Override
    public String name() {
        return "sobol";
    }

    /** Three 32-bit seeds: the index's scramble and each coordinate's; none for the one-point pattern. */
    @Override
    public int draws(int size) {
        return size == 1 ? 0 : 3;
    }

    /**
     * Points first .. first + count - 1 of the sequence scrambled with the pattern's seeds; the
     * one-point pattern's point is the centre.
     */
    @Override
    public void fill(PixelRandom random, int size, int first, int count, double[] xs, double[] ys) {
        if (size == 1) { // first is 0 and count 0 or 1
            for (int i = first; i < first + count; i++) {
                xs[i] = ys[i] = 0.5;
            }
            return;
        }
        int indexSeed = random.nextInt(), xSeed = random.nextInt(), ySeed = random.nextInt();
        points(indexSeed, xSeed, ySeed, first, count, xs, ys);
    }

    /**
     * Points first .. first + count - 1 of the sequence scrambled with the seeds {@link #fill}
     * draws (a pattern of more than one point), into xs and ys at the same indices: what fill gives,
     * for a caller that keeps a pixel's seeds across its runs ({@link PixelSamples}).
     */
    static void points(int indexSeed, int xSeed, int ySeed, int first, int count, double[] xs, double[] ys) {
        // owenScramble(b, s) = reverse(lkHash(reverse(b), s)); the reversals that cancel are left out.
        for (int i = first; i < first + count; i++) {
            int reversed = i < SMALL ? SMALL_REVERSED[i] : Integer.reverse(i);
            int index = Integer.reverse(lkHash(reversed, indexSeed));
            xs[i] = unit(Integer.reverse(lkHash(index, xSeed)));
            ys[i] = unit(Integer.reverse(lkHash(sobolSecondReversed(index), ySeed)));
        }
    }

    /** Indices below this have their bits reversed by a table: a pixel's first points. */
    private static final int SMALL = 256;
    private static final int[] SMALL_REVERSED = new int[SMALL];

    static {
        for (int i = 0; i < SMALL; i++) {
            SMALL_REVERSED[i] = Integer.reverse(i);
        }
    }

    /**
     * {@code Integer.reverse(sobolSecond(index))}, from four tables: the dimension is linear over
     * GF(2) in the index's bits, so each byte of the index contributes a fixed term.
     */
    static int sobolSecondReversed(int index) {
        return SECOND_REVERSED[index & 0xff] ^ SECOND_REVERSED[256 | (index >>> 8) & 0xff]
                ^ SECOND_REVERSED[512 | (index >>> 16) & 0xff] ^ SECOND_REVERSED[768 | index >>> 24];
    }

    /** Entry 256 k + b: the reversed second dimension of the index b << 8k. */
    private static final int[] SECOND_REVERSED = new int[1024];

    static {
        for (int k = 0; k < 4; k++) {
            for (int b = 0; b < 256; b++) {
                SECOND_REVERSED[256 * k + b] = Integer.reverse(sobolSecond(b << (8 * k)));
            }
        }
    }

    /** Sobol's second dimension as a 32-bit binary fraction (direction numbers v_k = v_{k-1} ^ v_{k-1} >> 1). */
    static int sobolSecond(int index) {
        int result = 0;
        for (int v = 1 << 31; index != 0; index >>>= 1, v ^= v >>> 1) {
            if ((index & 1) != 0) {
                result ^= v;
            }
        }
        return result;
    }

    /**
     * A nested uniform scramble of a 32-bit binary fraction: each bit is flipped or not depending on
     * the seed and on all the bits above it only, which keeps every elementary interval's points in
     * one elementary interval.
     */
    static int owenScramble(int bits, int seed) {
        return Integer.reverse(lkHash(Integer.reverse(bits), seed));
    }

    /** A bijection in which each output bit depends only on the same and lower input bits. */
    private static int lkHash(int x, int seed) {
        x ^= x * 0x3d20adea;
        x += seed;
        x *= (seed >>> 16) | 1;
        x ^= x * 0x05526c56;
        x ^= x * 0x53a22864;
        return x;
    }

    /** A 32-bit binary fraction as a double in [0, 1). */
    private static double unit(int bits) {
        return (bits & 0xffffffffL) * 0x1.0p-32;
    }
}

package studio.engine.sampler;

/** Small helpers the samplers share. */
final class Strata {

    /** The largest double below 1. */
    static final double ONE_BELOW = Math.nextDown(1.0);

    private Strata() {
    }

    /** Throws unless at least one sample is asked for. */
    static void requirePositive(int samplesPerPixel) {
        if (samplesPerPixel < 1) {
            throw new IllegalArgumentException("samples per pixel must be at least 1: " + samplesPerPixel);
        }
    }

    /**
     * The offset {@code (cell + u) / cells} of a sample in stratum {@code cell} of {@code cells}, kept below 1
     * (for u within a few ulps of 1 the sum and the division can round up to exactly 1).
     */
    static double offset(int cell, double u, int cells) {
        return Math.min((cell + u) / cells, ONE_BELOW);
    }

    /** The largest divisor of n not above its square root: the number of rows of an as-square-as-possible grid. */
    static int rows(int n) {
        int r = (int) Math.sqrt(n);
        while (n % r != 0) {
            r--;
        }
        return r;
    }
}

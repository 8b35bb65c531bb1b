package studio.engine.mesh;

/**
 * Exact decimal-to-double conversion of w * 10^q for significands of up to 19 digits, without
 * allocation: Clinger's fast path (w at most 2^53 and |q| at most 22: one correctly rounded
 * multiply or divide), else the Eisel-Lemire algorithm (Lemire, "Number parsing at a gigabyte per
 * second", 2021; as in fast_float): a 128-bit truncated power of five ({@link PowersOfFive}) times
 * the normalised significand, which decides the correctly rounded result unless the product lies
 * too close to a rounding boundary. In those rare cases, and for subnormal or overflowing results,
 * it returns NaN and the caller falls back to {@link Double#parseDouble}.
 */
final class DecimalToDouble {

    private static final int MIN_Q = PowersOfFive.MIN_Q, MAX_Q = PowersOfFive.MAX_Q;
    private static final long[] POWERS_OF_FIVE = PowersOfFive.TABLE;
    private static final double[] POWERS_OF_TEN = new double[23];

    static {
        double p = 1;
        for (int i = 0; i < POWERS_OF_TEN.length; i++) {
            POWERS_OF_TEN[i] = p;
            p *= 10;
        }
    }

    private DecimalToDouble() {
    }

    /**
     * The double nearest to w * 10^q (ties to even), w read as unsigned, or NaN when this method
     * cannot decide (the caller then parses the text with {@link Double#parseDouble}).
     */
    static double toDouble(long w, int q) {
        if (w == 0) {
            return 0;
        }
        if (q >= -22 && q <= 22 && w > 0 && w <= 1L << 53) {
            double d = w;
            return q < 0 ? d / POWERS_OF_TEN[-q] : d * POWERS_OF_TEN[q];
        }
        if (q < MIN_Q || q > MAX_Q) {
            return Double.NaN;
        }
        int lz = Long.numberOfLeadingZeros(w);
        w <<= lz;
        int i = 2 * (q - MIN_Q);
        long hi = unsignedMultiplyHigh(w, POWERS_OF_FIVE[i]);
        long lo = w * POWERS_OF_FIVE[i];
        if ((hi & 0x1FF) == 0x1FF) { // the low bits may matter: add the next 64 bits of the power
            long lo2 = unsignedMultiplyHigh(w, POWERS_OF_FIVE[i + 1]);
            long sum = lo + lo2;
            if (Long.compareUnsigned(sum, lo) < 0) {
                hi++;
            }
            lo = sum;
        }
        if (lo == -1L && (q < -27 || q > 55)) {
            return Double.NaN; // the truncated power may have cost a carry
        }
        int upperBit = (int) (hi >>> 63);
        long mantissa = hi >>> (upperBit + 9);
        int power2 = (int) ((217706L * q) >> 16) + 63 + upperBit - lz + 1023;
        if (power2 <= 0) {
            return Double.NaN; // subnormal
        }
        if (Long.compareUnsigned(lo, 1) <= 0 && q >= -4 && q <= 23 && (mantissa & 3) == 1
                && (mantissa << (upperBit + 9)) == hi) {
            mantissa &= ~1L; // exactly halfway: round to even, down here
        }
        mantissa += mantissa & 1;
        mantissa >>>= 1;
        if (mantissa >= 2L << 52) {
            mantissa = 1L << 52;
            power2++;
        }
        mantissa &= ~(1L << 52);
        if (power2 >= 0x7FF) {
            return Double.NaN; // overflow
        }
        return Double.longBitsToDouble((long) power2 << 52 | mantissa);
    }

    /** The high 64 bits of the unsigned 128-bit product (Math.unsignedMultiplyHigh arrives in Java 18). */
    private static long unsignedMultiplyHigh(long a, long b) {
        return Math.multiplyHigh(a, b) + ((a >> 63) & b) + ((b >> 63) & a);
    }
}

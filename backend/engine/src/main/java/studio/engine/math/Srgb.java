package studio.engine.math;

/** The sRGB transfer function (IEC 61966-2-1), both directions. */
public final class Srgb {

    private Srgb() {
    }

    /** Encoded sRGB value in [0, 1] to linear light. */
    public static double toLinear(double encoded) {
        return encoded <= 0.04045 ? encoded / 12.92 : Math.pow((encoded + 0.055) / 1.055, 2.4);
    }

    /** Linear light to an encoded sRGB value, clamped to [0, 1]; NaN maps to 0. */
    public static double fromLinear(double linear) {
        if (!(linear > 0)) {
            return 0;
        }
        if (linear >= 1) {
            return 1;
        }
        return linear <= 0.0031308 ? 12.92 * linear : 1.055 * Math.pow(linear, 1 / 2.4) - 0.055;
    }

    /**
     * Linear light to an 8-bit sRGB code value: exactly {@code round(fromLinear(linear) * 255)}, by
     * table. A guess from {@link #GUESS} (the code at the start of the value's 1/{@value #BUCKETS}
     * of [0, 1]; no bucket holds two code boundaries, the closest pair being about 1/3290 apart) is put
     * right against the exact boundaries: about 5 ns a value, where a binary search over the 255
     * boundaries took about 40 (eight unpredictable branches) and the formula's pow more.
     */
    public static int toByte(double linear) {
        if (!(linear > 0)) {
            return 0;
        }
        if (linear >= 1) {
            return 255;
        }
        int code = GUESS[(int) (linear * BUCKETS)];
        while (code < 255 && linear >= BOUNDARY[code]) {
            code++;
        }
        while (code > 0 && linear < BOUNDARY[code - 1]) {
            code--;
        }
        return code;
    }

    /** The code value by the formula (pow per call); {@link #toByte} is the same, faster. */
    static int toByteByFormula(double linear) {
        return (int) Math.round(fromLinear(linear) * 255);
    }

    /**
     * BOUNDARY[c] is the smallest double whose code is at least c + 1 (the formula is monotone:
     * Math.pow is semi-monotonic), found once by bisection over the ordered bit patterns.
     */
    private static final double[] BOUNDARY = new double[255];
    /** Buckets of [0, 1] for the first guess of {@link #toByte}. */
    private static final int BUCKETS = 4096;
    /** GUESS[i]: the code of i / {@value #BUCKETS}. */
    private static final int[] GUESS = new int[BUCKETS + 1];

    static {
        for (int c = 1; c <= 255; c++) {
            long lo = 0, hi = Double.doubleToRawLongBits(1.0); // code(lo) < c <= code(hi)
            while (hi - lo > 1) {
                long mid = (lo + hi) >>> 1;
                if (toByteByFormula(Double.longBitsToDouble(mid)) >= c) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            BOUNDARY[c - 1] = Double.longBitsToDouble(hi);
        }
        for (int i = 0; i <= BUCKETS; i++) {
            GUESS[i] = toByteByFormula((double) i / BUCKETS);
        }
    }
}

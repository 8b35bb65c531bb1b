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

    /** Linear light to an 8-bit sRGB code value. */
    public static int toByte(double linear) {
        return (int) Math.round(fromLinear(linear) * 255);
    }
}

package studio.bench;

import java.math.BigDecimal;
import java.math.MathContext;

import studio.engine.math.Rgb;
import studio.engine.math.Vec3;

/** Numbers and vectors as scene-description text: plain decimals in the C locale, never "1E-5" or "-0". */
final class Sdl {

    private static final MathContext DIGITS = new MathContext(15);

    private Sdl() {
    }

    /**
     * At most 15 significant digits (so 0.8 x 0.1 is written 0.08, not 0.08000000000000002), as a
     * plain decimal.
     */
    static String num(double v) {
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException("not a finite number: " + v);
        }
        if (v == 0) {
            return "0";
        }
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return BigDecimal.valueOf(v).round(DIGITS).stripTrailingZeros().toPlainString();
    }

    /** {@code <x, y, z>} */
    static String vec(Vec3 v) {
        return "<" + num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()) + ">";
    }

    /** {@code <r, g, b>} */
    static String rgb(Rgb c) {
        return "<" + num(c.r()) + ", " + num(c.g()) + ", " + num(c.b()) + ">";
    }
}

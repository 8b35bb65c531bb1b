package studio.engine.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.Random;

import org.junit.jupiter.api.Test;

/** The fast conversion gives exactly Double.parseDouble's bits, or declines (NaN); never a wrong last bit. */
class DecimalToDoubleTest {

    private static void assertSameAsParseDouble(long w, int q) {
        double fast = DecimalToDouble.toDouble(w, q);
        if (Double.isNaN(fast)) {
            return; // declined: the reader falls back to parseDouble
        }
        String text = Long.toUnsignedString(w) + "e" + q;
        assertEquals(Double.doubleToRawLongBits(Double.parseDouble(text)), Double.doubleToRawLongBits(fast), text);
    }

    @Test
    void randomSignificandsOfUpTo19DigitsAtEveryExponentMatchParseDouble() {
        Random random = new Random(21);
        int declined = 0, n = 1_000_000;
        for (int i = 0; i < n; i++) {
            int digits = 1 + random.nextInt(19);
            long w = 0;
            for (int d = 0; d < digits; d++) {
                w = w * 10 + random.nextInt(10);
            }
            int q = random.nextInt(600) - 320;
            assertSameAsParseDouble(w, q);
            if (Double.isNaN(DecimalToDouble.toDouble(w, q))) {
                declined++;
            }
        }
        assertTrue(declined < n / 50, "declined " + declined + " of " + n);
    }

    @Test
    void printedDoublesReadBackBitForBit() {
        Random random = new Random(22);
        int declined = 0;
        for (int i = 0; i < 1_000_000; i++) {
            double x = Math.abs(switch (i % 3) {
                case 0 -> random.nextGaussian();
                case 1 -> Double.longBitsToDouble(random.nextLong() & 0x7fefffffffffffffL);
                default -> random.nextDouble() * Math.pow(10, random.nextInt(40) - 20);
            }); // the sign is the reader's business
            BigDecimal exact = new BigDecimal(Double.toString(x));
            long w = exact.unscaledValue().longValueExact();
            int q = -exact.scale();
            double back = DecimalToDouble.toDouble(w, q);
            if (Double.isNaN(back)) {
                declined++;
            } else {
                assertEquals(Double.doubleToRawLongBits(x), Double.doubleToRawLongBits(back), Double.toString(x));
            }
        }
        assertTrue(declined < 20_000, "declined " + declined); // subnormals and the rare near-boundary case
    }

    @Test
    void exactHalfwayCasesRoundToEven() {
        // 2^53 + 1 lies halfway between 2^53 and 2^53 + 2: even is 2^53.
        assertEquals(9007199254740992.0, DecimalToDouble.toDouble(9007199254740993L, 0), 0.0);
        assertEquals(9007199254740996.0, DecimalToDouble.toDouble(9007199254740995L, 0), 0.0);
        Random random = new Random(23);
        for (int i = 0; i < 200_000; i++) {
            // k + 0.5 for k in [2^52, 2^53): halfway between neighbouring doubles, written with 17 digits.
            long k = (1L << 52) + (random.nextLong() >>> 12);
            assertSameAsParseDouble(10 * k + 5, -1);
            // odd multiples of 2^9 in [2^62, 2^63): halfway, 19 digits.
            long m = (1L << 62) + ((random.nextLong() >>> 2) & ~0x3ffL) + 0x200L;
            assertSameAsParseDouble(m, 0);
            assertSameAsParseDouble(m + (random.nextBoolean() ? 1 : -1), 0);
        }
    }

    @Test
    void zeroAndLimitsAreExactOrDeclined() {
        assertEquals(0.0, DecimalToDouble.toDouble(0, 5), 0.0);
        assertEquals(1.7976931348623157e308, DecimalToDouble.toDouble(17976931348623157L, 292), 0.0);
        assertTrue(Double.isNaN(DecimalToDouble.toDouble(1, 309)), "overflow declines");
        assertTrue(Double.isNaN(DecimalToDouble.toDouble(1, -320)), "subnormal declines");
        assertEquals(2.2250738585072014e-308, DecimalToDouble.toDouble(22250738585072014L, -324), 0.0);
    }
}

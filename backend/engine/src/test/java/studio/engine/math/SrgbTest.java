package studio.engine.math;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

/** The table-driven 8-bit encoding gives exactly the formula's code for every value, boundaries included. */
class SrgbTest {

    @Test
    void tableEqualsTheFormulaOnRandomValues() {
        SplittableRandom random = new SplittableRandom(11);
        for (int i = 0; i < 200_000; i++) {
            double x = i % 2 == 0 ? random.nextDouble() * 1.2 : Math.pow(10, -8 * random.nextDouble());
            assertEquals(Srgb.toByteByFormula(x), Srgb.toByte(x), "linear " + x);
        }
    }

    @Test
    void tableEqualsTheFormulaAroundEveryCodeBoundary() {
        for (int c = 0; c <= 255; c++) {
            // the linear value near the middle between codes c - 1 and c, then walk to the exact switch
            double x = Srgb.toLinear(Math.max(0, c - 0.5) / 255);
            for (int k = -3; k <= 3; k++) {
                double y = x;
                for (int step = 0; step < Math.abs(k); step++) {
                    y = k < 0 ? Math.nextDown(y) : Math.nextUp(y);
                }
                assertEquals(Srgb.toByteByFormula(y), Srgb.toByte(y), "linear " + y + " near code " + c);
            }
        }
    }

    @Test
    void clampsAndMapsNonFiniteValues() {
        for (double x : new double[] {Double.NaN, Double.NEGATIVE_INFINITY, -1, -0.0, 0, Double.MIN_VALUE, 1, 1.0001,
                Double.POSITIVE_INFINITY}) {
            assertEquals(Srgb.toByteByFormula(x), Srgb.toByte(x), "linear " + x);
        }
        assertEquals(0, Srgb.toByte(Double.NaN));
        assertEquals(255, Srgb.toByte(Double.POSITIVE_INFINITY));
    }
}

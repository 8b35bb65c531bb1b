package studio.engine.texture;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.math.Rgb;

/** The checker's closed-form box filter against the box's mean found by brute force. */
class CheckerTextureTest {

    /** The share of odd squares in the box, by a 400 x 400 grid of point samples. */
    private static double bruteForce(double s, double t, double ds, double dt) {
        int n = 400, odd = 0;
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                double x = s - ds + 2 * ds * (i + 0.5) / n, y = t - dt + 2 * dt * (j + 0.5) / n;
                odd += (Math.floor(x) + Math.floor(y)) % 2 == 0 ? 0 : 1;
            }
        }
        return (double) odd / (n * n);
    }

    @Test
    void closedFormIsTheBoxMean() {
        Random random = new Random(11);
        for (int i = 0; i < 300; i++) {
            double s = random.nextDouble() * 20 - 10, t = random.nextDouble() * 20 - 10;
            double ds = random.nextDouble() * 0.99, dt = random.nextDouble() * 0.99;
            assertEquals(bruteForce(s, t, ds, dt), CheckerTexture.secondShare(s, t, ds, dt), 0.01,
                    "box at " + s + ", " + t + " of half widths " + ds + ", " + dt);
        }
    }

    @Test
    void aPointReadsItsSquareAndAWideBoxTheMean() {
        assertEquals(0, CheckerTexture.secondShare(0.5, 0.5, 0, 0));
        assertEquals(1, CheckerTexture.secondShare(1.5, 0.5, 0, 0));
        assertEquals(1, CheckerTexture.secondShare(-0.5, 0.5, 0, 0));
        assertEquals(0, CheckerTexture.secondShare(1e9 + 0.5, 1e9 + 0.5, 1e-3, 1e-3));
        assertEquals(0.5, CheckerTexture.secondShare(3.2, 0.7, 5, 0.1));
        assertEquals(0.5, CheckerTexture.secondShare(3.2, 0.7, Double.POSITIVE_INFINITY, Double.NaN));
    }

    @Test
    void colourIsTheSharesMix() {
        CheckerTexture checks = new CheckerTexture(Rgb.BLACK, new Rgb(1, 0.5, 0.25), 2);
        double[] out = new double[3];
        checks.filtered(3, 1, 0, 0, 1, 1, false, out); // s = 1.5, t = 0.5: the second colour
        assertEquals(1, out[0]);
        assertEquals(0.25, out[2]);
        checks.filtered(3, 1, Double.POSITIVE_INFINITY, 0, 1, 1, false, out);
        assertEquals(0.5, out[0]);
        assertEquals(0.25, out[1]);
    }

    @Test
    void aroundASphereTheCountIsEvenSoTheSeamMatches() {
        CheckerTexture checks = new CheckerTexture(Rgb.BLACK, Rgb.WHITE, 1);
        double[] first = new double[3], last = new double[3];
        double metres = 2 * Math.PI * 1.3; // 8.17 squares around: 8
        checks.filtered(1e-6, 0.3, 0, 0, metres, 1, true, first);
        checks.filtered(1 - 1e-6, 0.3, 0, 0, metres, 1, true, last);
        assertEquals(1 - first[0], last[0]);
    }
}

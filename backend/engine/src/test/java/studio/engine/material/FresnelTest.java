package studio.engine.material;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/** Robustness case OPT-01 and OPT-02: exact Fresnel reflectance near the critical angle and at normal incidence. */
class FresnelTest {

    private static final double GLASS = 1.5;
    private static final double CRITICAL = Math.asin(1 / GLASS); // 41.8103148958 degrees

    @Test
    void leavingGlassBelowTheCriticalAngleReflectsPartOfTheLight() {
        double r30 = Fresnel.reflectance(Math.cos(Math.toRadians(30)), GLASS, 1);

        // s and p amplitudes by hand: cos_t = sqrt(1 - (1.5 * 0.5)^2) = sqrt(0.4375)
        double cosI = Math.sqrt(0.75), cosT = Math.sqrt(0.4375);
        double rs = (GLASS * cosI - cosT) / (GLASS * cosI + cosT), rp = (cosI - GLASS * cosT) / (cosI + GLASS * cosT);
        assertEquals((rs * rs + rp * rp) / 2, r30, 1e-15);
        assertTrue(r30 > 0.04 && r30 < 0.1, "R(30 deg) = " + r30);
    }

    @Test
    void leavingGlassAtAndBeyondTheCriticalAngleReflectsEverything() {
        for (double degrees : new double[] {41.8103148958, 45, 60, 89.9, 90}) {
            assertEquals(1.0, Fresnel.reflectance(Math.cos(Math.toRadians(degrees)), GLASS, 1), 0.0, degrees + " deg");
        }
    }

    @Test
    void leavingGlassWithinAPicoradianOfTheCriticalAngleStaysFiniteAndNearOne() {
        int total = 0;
        for (int k = 0; k <= 2000; k++) {
            double theta = CRITICAL - 1e-12 + 2e-12 * k / 2000;
            double r = Fresnel.reflectance(Math.cos(theta), GLASS, 1);
            assertTrue(r >= 0.99 && r <= 1, "R = " + r + " at critical angle " + (theta - CRITICAL) + " rad");
            if (theta >= CRITICAL + 1e-13) {
                assertEquals(1.0, r, 0.0, "total internal reflection at +" + (theta - CRITICAL) + " rad");
                total++;
            }
        }
        assertTrue(total > 800);
    }

    @Test
    void reflectanceRisesContinuouslyToOneAtTheCriticalAngle() {
        double below = Fresnel.reflectance(Math.cos(CRITICAL - Math.toRadians(0.01)), GLASS, 1);
        double above = Fresnel.reflectance(Math.cos(CRITICAL + Math.toRadians(0.01)), GLASS, 1);
        double halfDegreeBelow = Fresnel.reflectance(Math.cos(CRITICAL - Math.toRadians(0.5)), GLASS, 1);

        assertTrue(below >= 0.85, "R(theta_c - 0.01 deg) = " + below);
        assertEquals(0.892, below, 0.001, "exact Fresnel");
        assertEquals(1.0, above, 0.0);
        assertTrue(Math.abs(above - below) <= 0.15);
        assertTrue(halfDegreeBelow < below, "R(theta_c - 0.5 deg) = " + halfDegreeBelow);
        assertEquals(1.0, Fresnel.reflectance(Math.cos(CRITICAL + Math.toRadians(0.5)), GLASS, 1), 0.0);
    }

    @Test
    void reflectanceNeverFallsAsTheAngleGrows() {
        for (double[] etas : new double[][] {{1, GLASS}, {GLASS, 1}, {1, 2.4}}) {
            double previous = 0;
            for (int k = 0; k <= 9000; k++) {
                double r = Fresnel.reflectance(Math.cos(Math.toRadians(k / 100.0)), etas[0], etas[1]);
                assertTrue(r >= previous - 1e-15 && r <= 1, "R at " + k / 100.0 + " deg from " + etas[0]);
                previous = r;
            }
            assertEquals(1.0, previous, 1e-12, "grazing incidence reflects everything");
        }
    }

    @Test
    void normalIncidenceWithCosinesRoundedAboveOneGivesTheClosedForm() {
        // 100000 random unit d with n = normalize(-d): -d.n is 1 only up to rounding and can exceed it
        Random random = new Random(17);
        double expected = Math.pow((GLASS - 1) / (GLASS + 1), 2);
        int above = 0;
        for (int i = 0; i < 100_000; i++) {
            double x = random.nextGaussian(), y = random.nextGaussian(), z = random.nextGaussian();
            double len = Math.sqrt(x * x + y * y + z * z);
            double dx = x / len, dy = y / len, dz = z / len;
            double nLen = Math.sqrt(dx * dx + dy * dy + dz * dz);
            double nx = -dx / nLen, ny = -dy / nLen, nz = -dz / nLen;
            double cos = -(dx * nx + dy * ny + dz * nz);
            above += cos > 1 ? 1 : 0;

            assertEquals(expected, Fresnel.reflectance(cos, 1, GLASS), 1e-12);
            assertEquals(expected, Fresnel.reflectance(cos, GLASS, 1), 1e-12);
        }
        assertTrue(above > 0, "the sweep must contain cosines above 1");
    }
}

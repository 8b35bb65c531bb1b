package studio.engine.light;

import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

import studio.engine.math.Rgb;
import studio.engine.math.Vec3;

class SoftLightValidationTest {

    @Test
    void sphereLightRejectsARadiusThatIsNotFiniteAndPositive() {
        for (double radius : new double[] {0, -1, Double.NaN, Double.POSITIVE_INFINITY}) {
            assertThrows(IllegalArgumentException.class, () -> new SphereLight(Vec3.ZERO, radius, Rgb.WHITE, 1, false));
        }
    }

    @Test
    void areaLightRejectsBadSizesAndALookAtOnItsPosition() {
        Vec3 down = new Vec3(0, -1, 0);
        for (double size : new double[] {0, -1, Double.NaN, Double.POSITIVE_INFINITY}) {
            assertThrows(IllegalArgumentException.class,
                    () -> new AreaLight(Vec3.ZERO, size, 1, down, Rgb.WHITE, 1, false, false));
            assertThrows(IllegalArgumentException.class,
                    () -> new AreaLight(Vec3.ZERO, 1, size, down, Rgb.WHITE, 1, false, false));
        }
        assertThrows(IllegalArgumentException.class,
                () -> new AreaLight(new Vec3(1, 2, 3), 1, 1, new Vec3(1, 2, 3), Rgb.WHITE, 1, false, false));
        assertThrows(IllegalArgumentException.class,
                () -> new AreaLight(Vec3.ZERO, 1, 1, down, Rgb.WHITE, -1, false, false));
    }
}

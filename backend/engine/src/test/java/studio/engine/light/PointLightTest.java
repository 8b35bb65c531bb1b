package studio.engine.light;

import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

import studio.engine.math.Rgb;
import studio.engine.math.Vec3;

class PointLightTest {

    @Test
    void pointLightRejectsNonFinitePositionAndNegativeOrNonFiniteIntensity() {
        assertThrows(IllegalArgumentException.class,
                () -> new PointLight(new Vec3(Double.NaN, 0, 0), Rgb.WHITE, 1, false));
        assertThrows(IllegalArgumentException.class, () -> new PointLight(Vec3.ZERO, Rgb.WHITE, -1, false));
        assertThrows(IllegalArgumentException.class, () -> new PointLight(Vec3.ZERO, Rgb.WHITE, Double.NaN, false));
        assertThrows(IllegalArgumentException.class,
                () -> new PointLight(Vec3.ZERO, Rgb.WHITE, Double.POSITIVE_INFINITY, true));
    }

    @Test
    void pointLightRejectsMissingNegativeOrNonFiniteColourBeforeRendering() {
        // Otherwise a null colour throws mid-render and a NaN one silently blackens every lit pixel.
        assertThrows(IllegalArgumentException.class, () -> new PointLight(Vec3.ZERO, null, 1, false));
        for (Rgb color : new Rgb[] {new Rgb(Double.NaN, 1, 1), new Rgb(1, -0.5, 1),
                new Rgb(1, 1, Double.POSITIVE_INFINITY)}) {
            assertThrows(IllegalArgumentException.class, () -> new PointLight(Vec3.ZERO, color, 1, false),
                    "colour " + color);
        }
    }
}

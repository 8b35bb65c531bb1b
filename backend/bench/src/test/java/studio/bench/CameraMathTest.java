package studio.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class CameraMathTest {

    @Test
    void horizontalFovOfASquareImageIsTheVerticalOne() {
        assertEquals(50, CameraMath.horizontalFovDegrees(50, 1), 1e-12);
    }

    @Test
    void horizontalFovWidensWithTheAspectByTheTangentOfHalfTheAngle() {
        // 800x600 at 40 degrees vertical (the still life): 2 atan(4/3 tan 20deg) = 51.774 degrees
        double h = CameraMath.horizontalFovDegrees(40, 800.0 / 600);
        assertEquals(51.77400875924256, h, 1e-9);
        assertEquals(Math.tan(Math.toRadians(20)) * 4 / 3, Math.tan(Math.toRadians(h / 2)), 1e-12);
    }

    @Test
    void verticalAndHorizontalConversionsAreInverse() {
        for (double v = 1; v < 180; v += 7.3) {
            for (double aspect : new double[] {0.25, 0.75, 1, 4.0 / 3, 16.0 / 9, 5}) {
                double h = CameraMath.horizontalFovDegrees(v, aspect);
                assertEquals(v, CameraMath.verticalFovDegrees(h, aspect), 1e-9, "v=" + v + " aspect=" + aspect);
                assertEquals(true, h > 0 && h < 180);
            }
        }
    }
}

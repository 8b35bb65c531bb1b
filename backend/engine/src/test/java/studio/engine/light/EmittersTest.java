package studio.engine.light;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.geometry.Ray;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;

class EmittersTest {

    @Test
    void aRaySeesASphereLightAsItsColourTimesIntensity() {
        Emitters e = new Emitters(List.of(new PointLight(Vec3.ZERO, Rgb.WHITE, 1, false),
                new SphereLight(new Vec3(0, 0, -5), 1, new Rgb(0.5, 0.25, 1), 2, true)));

        assertTrue(e.any());
        assertTrue(e.nearest(new Ray(0, 0, 0, 0, 0, -1), Double.POSITIVE_INFINITY));
        assertEquals(1, e.r);
        assertEquals(0.5, e.g);
        assertEquals(2, e.b);
        assertFalse(e.nearest(new Ray(0, 0, 0, 0, 0, -1), 3.9), "an object in front hides it");
        assertFalse(e.nearest(new Ray(0, 0, 0, 0, 1, 0), Double.POSITIVE_INFINITY));
    }

    @Test
    void pointLightsHaveNothingToSee() {
        assertFalse(new Emitters(List.of(new PointLight(Vec3.ZERO, Rgb.WHITE, 1, false))).any());
    }

    @Test
    void aOneSidedRectangleIsSeenFromItsFrontOnly() {
        AreaLight down = new AreaLight(new Vec3(0, 2, 0), 2, 1, Vec3.ZERO, Rgb.WHITE, 3, false, false);
        Emitters e = new Emitters(List.of(down));

        assertTrue(e.nearest(new Ray(0.9, 0, 0.4, 0, 1, 0), Double.POSITIVE_INFINITY), "from below, inside");
        assertEquals(3, e.r);
        assertFalse(e.nearest(new Ray(1.1, 0, 0, 0, 1, 0), Double.POSITIVE_INFINITY), "beside its width");
        assertFalse(e.nearest(new Ray(0, 0, 0.6, 0, 1, 0), Double.POSITIVE_INFINITY), "beside its height");
        assertFalse(e.nearest(new Ray(0, 4, 0, 0, -1, 0), Double.POSITIVE_INFINITY), "from behind");
        assertTrue(new Emitters(List.of(new AreaLight(new Vec3(0, 2, 0), 2, 1, Vec3.ZERO, Rgb.WHITE, 3, false, true)))
                .nearest(new Ray(0, 4, 0, 0, -1, 0), Double.POSITIVE_INFINITY), "two-sided, from behind");
    }

    /** Edge-on: a ray in the rectangle's plane, along it and through its centre, sees nothing and makes no NaN. */
    @Test
    void aRectangleSeenEdgeOnIsNotSeen() {
        for (boolean twoSided : new boolean[] {false, true}) {
            Emitters e = new Emitters(List.of(new AreaLight(new Vec3(0, 2, 0), 2, 1, Vec3.ZERO, Rgb.WHITE, 3, false,
                    twoSided)));
            assertFalse(e.nearest(new Ray(-5, 2, 0, 1, 0, 0), Double.POSITIVE_INFINITY));
            assertFalse(e.nearest(new Ray(0, 2, -5, 0, 0, 1), Double.POSITIVE_INFINITY));
        }
    }
}

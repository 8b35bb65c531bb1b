package studio.engine.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * A {@link WideRay} set up again and again (rays from one origin reuse what was worked out from it)
 * holds exactly what a fresh one set up for the same ray holds: the float box test then keeps the
 * same boxes whatever rays came before.
 */
class WideRayTest {

    @Test
    void aReusedRayHoldsWhatAFreshOneHoldsWhateverOriginsCameBefore() {
        Random random = new Random(5);
        double[] coordinates = {0, -0.0, 1, -1, 0.1, 1e-40, 3e38, 2e30, -7.25, Double.NaN, Double.POSITIVE_INFINITY};
        WideRay reused = new WideRay();
        for (int i = 0; i < 20_000; i++) {
            double ox = pick(random, coordinates), oy = pick(random, coordinates), oz = pick(random, coordinates);
            int rays = 1 + random.nextInt(3);
            for (int k = 0; k < rays; k++) {
                // the same origin again, or one that differs on a single axis
                if (k > 0 && random.nextBoolean()) {
                    switch (random.nextInt(3)) {
                        case 0 -> ox = pick(random, coordinates);
                        case 1 -> oy = pick(random, coordinates);
                        default -> oz = pick(random, coordinates);
                    }
                }
                double dx = random.nextGaussian(), dy = random.nextGaussian(), dz = random.nextInt(8) == 0 ? 0 : random.nextGaussian();
                reused.set(ox, oy, oz, dx, dy, dz);
                WideRay fresh = new WideRay().set(ox, oy, oz, dx, dy, dz);
                String ray = "ray " + ox + " " + oy + " " + oz + " along " + dx + " " + dy + " " + dz;
                assertEquals(fresh.acceptAll, reused.acceptAll, ray);
                assertEquals(Float.floatToRawIntBits(fresh.nearOx), Float.floatToRawIntBits(reused.nearOx), ray);
                assertEquals(Float.floatToRawIntBits(fresh.farOx), Float.floatToRawIntBits(reused.farOx), ray);
                assertEquals(Float.floatToRawIntBits(fresh.nearOy), Float.floatToRawIntBits(reused.nearOy), ray);
                assertEquals(Float.floatToRawIntBits(fresh.farOy), Float.floatToRawIntBits(reused.farOy), ray);
                assertEquals(Float.floatToRawIntBits(fresh.nearOz), Float.floatToRawIntBits(reused.nearOz), ray);
                assertEquals(Float.floatToRawIntBits(fresh.farOz), Float.floatToRawIntBits(reused.farOz), ray);
                assertEquals(fresh.nearX + " " + fresh.nearY + " " + fresh.nearZ + " " + fresh.ix + " " + fresh.iy + " " + fresh.iz,
                        reused.nearX + " " + reused.nearY + " " + reused.nearZ + " " + reused.ix + " " + reused.iy + " " + reused.iz, ray);
            }
        }
    }

    @Test
    void aNewRayFromTheOriginIsSetUpAsAnyOther() {
        WideRay ray = new WideRay().set(0, 0, 0, 1, -2, 0.5);
        assertEquals(0f, ray.nearOx);
        assertEquals(0f, ray.farOz);
        assertEquals(false, ray.acceptAll);
        WideRay far = new WideRay().set(0, 0, 0, 1, -2, 0.5).set(1e31, 0, 0, 1, -2, 0.5);
        assertEquals(true, far.acceptAll, "an origin beyond 1e30 is out of range");
    }

    private static double pick(Random random, double[] values) {
        double v = values[random.nextInt(values.length)];
        return random.nextBoolean() ? v : v * (1 + random.nextDouble());
    }
}

package studio.engine.light;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.math.Rgb;
import studio.engine.math.Vec3;

class LightSamplerTest {

    private static final Vec3 AT = new Vec3(0.3, 4, -0.2);

    /** The mean of what a light gives a point facing up at p (times the cosine there) over an n x n grid of cell centres. */
    private static double irradiance(Light light, double px, double py, double pz, int n) {
        LightSampler s = new LightSampler(List.of(light));
        double sum = 0;
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                if (s.sample(0, px, py, pz, (i + 0.5) / n, (j + 0.5) / n) && s.ly > 0) {
                    sum += s.r * s.ly;
                }
            }
        }
        return sum / (n * n);
    }

    @Test
    void aPointLightGivesItsIntensityOverTheSquaredDistanceWithFalloff() {
        LightSampler s = new LightSampler(List.of(new PointLight(AT, Rgb.WHITE, 8, true)));

        assertTrue(s.sample(0, 0.3, 0, -0.2, 0.1, 0.9));
        assertEquals(0.5, s.r, 1e-15);
        assertEquals(1, s.ly, 1e-15);
        assertEquals(4, s.ty);
        assertTrue(s.sample(0, 0.3, 0, -0.2, 0.7, 0.05));
        assertEquals(4, s.ty, "every shadow ray to a point light ends at its one point, whatever (u, v)");
        assertEquals(0.5, s.r, 1e-15);
    }

    @Test
    void aTinySphereLightLightsAsThePointLightAtItsCentre() {
        for (boolean falloff : new boolean[] {false, true}) {
            LightSampler point = new LightSampler(List.of(new PointLight(AT, Rgb.WHITE, 3, falloff)));
            LightSampler sphere = new LightSampler(List.of(new SphereLight(AT, 1e-6, Rgb.WHITE, 3, falloff)));
            point.sample(0, 1, 0.5, 2, 0, 0);
            for (double u : new double[] {0, 0.3, 0.999}) {
                assertTrue(sphere.sample(0, 1, 0.5, 2, u, 1 - u));
                assertEquals(point.r, sphere.r, 1e-6 * point.r);
                assertEquals(point.lx, sphere.lx, 1e-6);
                assertEquals(point.ly, sphere.ly, 1e-6);
                assertEquals(point.lz, sphere.lz, 1e-6);
            }
        }
    }

    @Test
    void sphereSamplesLieOnTheSphereInsideTheVisibleCap() {
        Vec3 c = new Vec3(1, 5, -2);
        double radius = 1.5;
        LightSampler s = new LightSampler(List.of(new SphereLight(c, radius, Rgb.WHITE, 1, true)));
        double d = c.length(), cosMax = Math.sqrt(d * d - radius * radius) / d;
        for (int i = 0; i < 32; i++) {
            for (int j = 0; j < 32; j++) {
                assertTrue(s.sample(0, 0, 0, 0, (i + 0.5) / 32, (j + 0.5) / 32));
                Vec3 t = new Vec3(s.tx, s.ty, s.tz);
                assertEquals(radius, t.minus(c).length(), 1e-12);
                double cos = (s.lx * c.x() + s.ly * c.y() + s.lz * c.z()) / d;
                assertTrue(cos >= cosMax - 1e-12, "outside the cap: " + cos);
                assertEquals(1, s.lx * s.lx + s.ly * s.ly + s.lz * s.lz, 1e-12);
                // the sample's point is on the near side: the ray to it leaves the sphere's surface outward
                assertTrue(t.minus(c).dot(new Vec3(s.lx, s.ly, s.lz)) <= 1e-12);
            }
        }
    }

    /** A sphere wholly above a point's horizon gives I / d^2 with fall-off, whatever its radius (the point light's). */
    @Test
    void aSphereLightsAsAPointLightWithFalloffWhateverItsRadius() {
        for (double radius : new double[] {0.01, 1, 3.5}) {
            double e = irradiance(new SphereLight(new Vec3(0, 4, 0), radius, Rgb.WHITE, 16, true), 0, 0, 0, 64);
            assertEquals(1, e, 2e-3, "radius " + radius);
        }
    }

    /** Radius 100 with its surface 0.01 above the point: finite, and never above twice the irradiance. */
    @Test
    void aHugeSphereJustAboveAPointGivesFiniteBoundedSamples() {
        LightSampler s = new LightSampler(List.of(new SphereLight(new Vec3(0, 100.01, 0), 100, Rgb.WHITE, 1, true)));
        double d = 100.01, bound = 2 / (d * d);
        for (int i = 0; i < 64; i++) {
            for (int j = 0; j < 64; j++) {
                assertTrue(s.sample(0, 0, 0, 0, (i + 0.5) / 64, (j + 0.5) / 64));
                assertTrue(Double.isFinite(s.r) && s.r <= bound && s.r > 0, "sample " + s.r);
                assertTrue(s.ty >= 0.01 - 1e-12 && s.ty < 200.01, "point " + s.ty);
            }
        }
        double e = irradiance(new SphereLight(new Vec3(0, 100.01, 0), 100, Rgb.WHITE, 1, true), 0, 0, 0, 64);
        assertEquals(1 / (d * d), e, 1e-3 / (d * d));
    }

    /**
     * Sphere samples are uniform in the solid angle of the cap: over a fine grid of (u, v), each
     * quarter of the cone around its axis, the half on either side of a plane through the axis
     * and the inner cone of half the solid angle each get their share.
     */
    @Test
    void sphereSamplesAreUniformInTheCapsSolidAngle() {
        Vec3 c = new Vec3(0.4, 3, -0.7);
        double radius = 1.2, px = 0.1, py = 0.2, pz = 0.3;
        LightSampler s = new LightSampler(List.of(new SphereLight(c, radius, Rgb.WHITE, 1, true)));
        Vec3 axis = c.minus(new Vec3(px, py, pz));
        double d = axis.length();
        Vec3 w = axis.normalized(), e = w.cross(new Vec3(1, 0, 0)).normalized(), f = w.cross(e);
        double cosMax = Math.sqrt((d - radius) * (d + radius)) / d, cosHalf = 1 - (1 - cosMax) / 2;
        int n = 512, inner = 0, positiveE = 0;
        int[] quadrant = new int[4];
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                assertTrue(s.sample(0, px, py, pz, (i + 0.5) / n, (j + 0.5) / n));
                double cos = s.lx * w.x() + s.ly * w.y() + s.lz * w.z();
                double alongE = s.lx * e.x() + s.ly * e.y() + s.lz * e.z();
                double alongF = s.lx * f.x() + s.ly * f.y() + s.lz * f.z();
                assertTrue(cos >= cosMax - 1e-12, "inside the cone");
                if (cos > cosHalf) {
                    inner++;
                }
                positiveE += alongE > 0 ? 1 : 0;
                quadrant[(alongE > 0 ? 1 : 0) + (alongF > 0 ? 2 : 0)]++;
            }
        }
        double all = (double) n * n;
        assertEquals(0.5, inner / all, 1e-3, "the inner cone of half the solid angle");
        assertEquals(0.5, positiveE / all, 1e-3, "either side of a plane through the axis");
        for (int q : quadrant) {
            assertEquals(0.25, q / all, 1e-3, "a quarter of the cone");
        }
    }

    /**
     * A stratum of (u, v) is a compact piece of the cap, not a ring or a half-wedge: each cell of a
     * 2 x 2 grid goes to one quarter of the cone around its axis (any two of its directions, seen
     * along the axis, at most 90 degrees apart), so a shadow edge across the light cuts few strata.
     */
    @Test
    void eachQuarterOfTheSquareSamplesOneQuarterOfTheCap() {
        Vec3 c = new Vec3(-1, 5, 2);
        LightSampler s = new LightSampler(List.of(new SphereLight(c, 0.8, Rgb.WHITE, 1, false)));
        Vec3 w = c.normalized();
        int n = 24;
        for (int cell = 0; cell < 4; cell++) {
            Vec3[] across = new Vec3[n * n];
            for (int i = 0; i < n; i++) {
                for (int j = 0; j < n; j++) {
                    double u = (cell % 2 + (i + 0.5) / n) / 2, v = (cell / 2 + (j + 0.5) / n) / 2;
                    assertTrue(s.sample(0, 0, 0, 0, u, v));
                    Vec3 l = new Vec3(s.lx, s.ly, s.lz);
                    across[i * n + j] = l.minus(w.times(l.dot(w))).normalized();
                }
            }
            for (Vec3 a : across) {
                for (Vec3 b : across) {
                    assertTrue(a.dot(b) > -1e-9, "cell " + cell + ": " + a + " and " + b + " more than 90 degrees apart");
                }
            }
        }
    }

    @Test
    void aPointInsideASphereLightGetsNothingFromIt() {
        LightSampler s = new LightSampler(List.of(new SphereLight(Vec3.ZERO, 1, Rgb.WHITE, 1, false)));

        assertFalse(s.sample(0, 0.5, 0, 0, 0.5, 0.5));
    }

    /** Irradiance at distance c on the axis of a Lambertian w x h rectangle of radiance L: pi L times the form factor. */
    private static double rectangleIrradiance(double radiance, double w, double h, double c) {
        double a = w / 2 / c, b = h / 2 / c;
        double corner = (a / Math.sqrt(1 + a * a) * Math.atan(b / Math.sqrt(1 + a * a))
                + b / Math.sqrt(1 + b * b) * Math.atan(a / Math.sqrt(1 + b * b))) / (2 * Math.PI);
        return Math.PI * radiance * 4 * corner;
    }

    @Test
    void anAreaLightGivesTheLambertianRectanglesIrradianceWithFalloff() {
        AreaLight light = new AreaLight(new Vec3(0, 2, 0), 3, 1.5, new Vec3(0, 0, 0), Rgb.WHITE, 9, true, false);
        double exact = rectangleIrradiance(9 / (3 * 1.5), 3, 1.5, 2);

        assertEquals(exact, irradiance(light, 0, 0, 0, 64), 1e-3 * exact);
    }

    @Test
    void aTinyAreaLightLightsAsAPointLightOnItsAxis() {
        AreaLight area = new AreaLight(AT, 1e-6, 1e-6, new Vec3(0.3, 0, -0.2), Rgb.WHITE, 5, true, false);
        LightSampler s = new LightSampler(List.of(area));
        assertTrue(s.sample(0, 0.3, 0, -0.2, 0.2, 0.7));
        assertEquals(5 / 16.0, s.r, 1e-9);
        double tx = s.tx, tz = s.tz;
        assertTrue(s.sample(0, 0.3, 0, -0.2, 0.9, 0.1));
        assertTrue(s.tx != tx || s.tz != tz, "another (u, v), another point on the light");
    }

    @Test
    void aOneSidedAreaLightGivesNothingBehindItOrInItsPlane() {
        AreaLight down = new AreaLight(new Vec3(0, 2, 0), 1, 1, Vec3.ZERO, Rgb.WHITE, 1, false, false);
        LightSampler s = new LightSampler(List.of(down));
        assertFalse(s.sample(0, 0, 3, 0, 0.5, 0.5), "behind");
        assertFalse(s.sample(0, 5, 2, 0, 0.5, 0.5), "edge-on, in its plane");

        LightSampler both = new LightSampler(List.of(new AreaLight(new Vec3(0, 2, 0), 1, 1, Vec3.ZERO, Rgb.WHITE, 1,
                false, true)));
        assertTrue(both.sample(0, 0, 3, 0, 0.5, 0.5));
        assertEquals(1, both.r, 1e-15);
    }

    /** As three.js: width along x when the light faces straight down; along the horizontal across the aim otherwise. */
    @Test
    void anAreaLightsWidthRunsAlongTheHorizontalAxisAcrossItsAim() {
        AreaLight down = new AreaLight(new Vec3(0, 2, 0), 4, 1, Vec3.ZERO, Rgb.WHITE, 1, false, false);
        assertEquals(1, Math.abs(down.widthAxis().x()), 1e-15);
        assertEquals(1, Math.abs(down.heightAxis().z()), 1e-15);
        AreaLight facingX = new AreaLight(Vec3.ZERO, 4, 1, new Vec3(-3, 0, 0), Rgb.WHITE, 1, false, false);
        assertEquals(1, Math.abs(facingX.widthAxis().z()), 1e-15);
        assertEquals(1, facingX.heightAxis().y(), 1e-15);
    }
}

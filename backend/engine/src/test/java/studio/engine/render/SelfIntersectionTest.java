package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import studio.engine.camera.Camera;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Sphere;
import studio.engine.light.PointLight;
import studio.engine.material.Material;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.sampler.RegularSampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/**
 * Robustness section "Self-intersection" (docs/robustness.md). Scene S: plane y=0, unit sphere resting on it at (0,1,0), point light at (3,6,2)
 * without fall-off, camera (0,3,6) looking at (0,0.5,0), fov 50, 128 x 128, one sample at each pixel centre.
 * Every position p becomes s*p + T. The shadow state of each pixel is worked out analytically; "acne" is a
 * lit pixel rendered shadowed, a "leak" a shadowed pixel rendered lit, counted on interior pixels: those whose
 * 3x3 neighbourhood (clipped at the image border) shows the same object and shadow state in the analytic
 * reference.
 */
class SelfIntersectionTest {

    private static final int SIZE = 128;
    private static final int BACKGROUND = 0, PLANE = 1, SPHERE = 2;
    private static final double AMBIENT = 0.1;
    private static final Material PLANE_MATERIAL = MaterialDefaults.of(MaterialKind.CHALK, new Rgb(0.8, 0, 0));
    private static final Material SPHERE_MATERIAL = MaterialDefaults.of(MaterialKind.CHALK, new Rgb(0, 0.8, 0));
    /** A pixel is shadowed when its value is exactly the ambient term. */
    private static final double PLANE_SHADOWED =
            PLANE_MATERIAL.color().times(PLANE_MATERIAL.diffuse()).r() * AMBIENT;
    private static final double SPHERE_SHADOWED =
            SPHERE_MATERIAL.color().times(SPHERE_MATERIAL.diffuse()).g() * AMBIENT;

    /** Analytic reference for s = 1, T = 0: object per pixel, lit state, interior mask. */
    private static final Reference REFERENCE = Reference.compute();
    private static final Film UNTRANSFORMED = render(1, 0);

    static Stream<Arguments> transforms() {
        return Stream.of(Arguments.of(1.0, 0.0), Arguments.of(1.0, 1e5), Arguments.of(1.0, 1e12),
                Arguments.of(1e-4, 0.0), Arguments.of(1e4, 0.0), Arguments.of(1e-8, 0.0), Arguments.of(1e8, 0.0));
    }

    @Test
    void analyticReferenceHasTheInteriorPixelCountsOfStability() {
        assertEquals(14683, REFERENCE.lit + REFERENCE.shadowed, "interior pixels");
        assertEquals(13990, REFERENCE.lit, "lit interior pixels");
        assertEquals(693, REFERENCE.shadowed, "shadowed interior pixels");
    }

    @ParameterizedTest(name = "scale {0}, translated by ({1},{1},{1})")
    @MethodSource("transforms")
    void sceneSHasNoShadowAcneAndNoLeaksOnInteriorPixels(double s, double t) {
        Film film = s == 1 && t == 0 ? UNTRANSFORMED : render(s, t);
        int acne = 0, leaks = 0, wrongObject = 0;
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                if (!REFERENCE.interior[y][x]) {
                    continue;
                }
                int object = objectOf(film, x, y);
                if (object != REFERENCE.object[y][x]) {
                    wrongObject++;
                } else if (REFERENCE.lit(x, y) && isShadowed(film, x, y, object)) {
                    acne++;
                } else if (!REFERENCE.lit(x, y) && !isShadowed(film, x, y, object)) {
                    leaks++;
                }
            }
        }
        assertEquals(0, wrongObject, "interior pixels showing the wrong object");
        assertEquals(0, acne, "acne: lit pixels rendered shadowed");
        assertEquals(0, leaks, "leaks: shadowed pixels rendered lit");
    }

    @ParameterizedTest(name = "scale {0}, translated by ({1},{1},{1})")
    @MethodSource("transforms")
    void sceneSMovedOrScaledMatchesTheUntransformedRenderWithinOne8BitStep(double s, double t) {
        Film film = render(s, t);
        double sum = 0;
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                for (int c = 0; c < 3; c++) {
                    double d = film.get(x, y, c) - UNTRANSFORMED.get(x, y, c);
                    sum += d * d;
                }
            }
        }
        double rmse = Math.sqrt(sum / (3.0 * SIZE * SIZE));
        assertTrue(rmse < 1.0 / 255, "linear RMSE " + rmse);
    }

    @Test
    void lightLyingOnAPlaneCastsNoSpuriousShadowsOnTheSphereItFaces() {
        // SELF-05 a: the plane is defined through the light L, so every shadow ray ends exactly on it.
        Vec3 light = new Vec3(0.37, 0, -0.21), normal = new Vec3(0.2, 1, -0.1).normalized();
        Vec3 center = new Vec3(0.37, 2, -0.21);
        Camera camera = new Camera(new Vec3(4, 0.3, 4), new Vec3(0, 1.5, 0), new Vec3(0, 1, 0), 40);
        Scene scene = new Scene(camera, List.of(new SceneObject(new Plane(light, normal), PLANE_MATERIAL),
                new SceneObject(new Sphere(center, 1), SPHERE_MATERIAL)),
                List.of(new PointLight(light, Rgb.WHITE, 1, false)), new Rgb(0, 0, 0.5), AMBIENT);

        RenderResult result = Renderer.render(RenderRequest.of(scene, new RenderSettings(SIZE, SIZE, new RegularSampler(1), 1, 2)));

        assertEquals(0, result.nonFiniteSamples());
        int facing = 0, dark = 0;
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                if (objectOf(result.film(), x, y) != SPHERE) {
                    continue;
                }
                Ray ray = camera.ray(2 * (x + 0.5) / SIZE - 1, 1 - 2 * (y + 0.5) / SIZE, 1);
                Vec3 p = firstSphereHit(ray.origin(), ray.direction(), center, 1);
                if (p == null || p.minus(center).dot(light.minus(p).normalized()) <= 0.05) {
                    continue;
                }
                facing++;
                if (isShadowed(result.film(), x, y, SPHERE)) {
                    dark++;
                }
            }
        }
        assertEquals(803, facing, "light-facing sphere pixels (robustness case SELF-05 counts 803)");
        assertEquals(0, dark, "light-facing sphere pixels with no direct light, of " + facing);
    }

    @Test
    void pointExactlyAtTheLightGetsOnlyAmbientAndStaysFinite() {
        // SELF-05 b: a primary ray down onto the plane lands exactly on the light: |L - p| = 0.
        Vec3 light = new Vec3(0.37, 0, -0.21), normal = new Vec3(0.2, 1, -0.1).normalized();
        Scene scene = new Scene(new Camera(new Vec3(4, 0.3, 4), new Vec3(0, 1.5, 0), new Vec3(0, 1, 0), 40),
                List.of(new SceneObject(new Plane(light, normal), PLANE_MATERIAL),
                        new SceneObject(new Sphere(new Vec3(0.37, 2, -0.21), 1), SPHERE_MATERIAL)),
                List.of(new PointLight(light, Rgb.WHITE, 1, false)), new Rgb(0, 0, 0.5), AMBIENT);

        Rgb c = Radiance.of(new Integrator(scene, 1, 0), new Ray(0.37, 0.5, -0.21, 0, -1, 0));

        assertEquals(new Rgb(PLANE_SHADOWED, 0, 0), c);
    }

    // --- rendering and reading scene S ---------------------------------------------------------------------

    private static Film render(double s, double t) {
        Vec3 shift = new Vec3(t, t, t);
        Camera camera = new Camera(new Vec3(0, 3, 6).times(s).plus(shift), new Vec3(0, 0.5, 0).times(s).plus(shift),
                new Vec3(0, 1, 0), 50);
        Scene scene = new Scene(camera,
                List.of(new SceneObject(new Plane(shift, new Vec3(0, 1, 0)), PLANE_MATERIAL),
                        new SceneObject(new Sphere(new Vec3(0, 1, 0).times(s).plus(shift), s), SPHERE_MATERIAL)),
                List.of(new PointLight(new Vec3(3, 6, 2).times(s).plus(shift), Rgb.WHITE, 1, false)),
                new Rgb(0, 0, 0.5), AMBIENT);
        RenderResult result = Renderer.render(RenderRequest.of(scene, new RenderSettings(SIZE, SIZE, new RegularSampler(1), 1, 2)));
        assertEquals(0, result.nonFiniteSamples());
        return result.film();
    }

    private static int objectOf(Film film, int x, int y) {
        boolean red = film.get(x, y, 0) > 0, green = film.get(x, y, 1) > 0;
        return red && !green ? PLANE : green && !red ? SPHERE : BACKGROUND;
    }

    private static boolean isShadowed(Film film, int x, int y, int object) {
        return object == PLANE ? film.get(x, y, 0) == PLANE_SHADOWED : film.get(x, y, 1) == SPHERE_SHADOWED;
    }

    /** The nearer intersection of o + t d (t > 0) with the sphere, by the textbook formula, or null. */
    private static Vec3 firstSphereHit(Vec3 o, Vec3 d, Vec3 center, double radius) {
        Vec3 f = o.minus(center);
        double a = d.dot(d), b = f.dot(d), c = f.dot(f) - radius * radius;
        double disc = b * b - a * c;
        if (disc <= 0) {
            return null;
        }
        double t = (-b - Math.sqrt(disc)) / a;
        return t > 0 ? o.plus(d.times(t)) : null;
    }

    /** Scene S at s = 1, T = 0 solved analytically at every pixel centre. */
    private static final class Reference {
        final int[][] object = new int[SIZE][SIZE];
        final boolean[][] litState = new boolean[SIZE][SIZE];
        final boolean[][] interior = new boolean[SIZE][SIZE];
        int lit, shadowed;

        boolean lit(int x, int y) {
            return litState[y][x];
        }

        static Reference compute() {
            Reference r = new Reference();
            Camera camera = new Camera(new Vec3(0, 3, 6), new Vec3(0, 0.5, 0), new Vec3(0, 1, 0), 50);
            Vec3 center = new Vec3(0, 1, 0), light = new Vec3(3, 6, 2);
            for (int y = 0; y < SIZE; y++) {
                for (int x = 0; x < SIZE; x++) {
                    Ray ray = camera.ray(2 * (x + 0.5) / SIZE - 1, 1 - 2 * (y + 0.5) / SIZE, 1);
                    Vec3 o = ray.origin(), d = ray.direction();
                    Vec3 p = firstSphereHit(o, d, center, 1);
                    if (p != null) {
                        r.object[y][x] = SPHERE;
                        r.litState[y][x] = p.minus(center).dot(light.minus(p)) > 0;
                    } else if (d.y() < 0) {
                        Vec3 q = o.plus(d.times(-o.y() / d.y()));
                        r.object[y][x] = PLANE;
                        r.litState[y][x] = !segmentMeetsSphere(q, light, center, 1);
                    }
                }
            }
            for (int y = 0; y < SIZE; y++) {
                for (int x = 0; x < SIZE; x++) {
                    boolean same = r.object[y][x] != BACKGROUND;
                    for (int j = Math.max(0, y - 1); j <= Math.min(SIZE - 1, y + 1) && same; j++) {
                        for (int i = Math.max(0, x - 1); i <= Math.min(SIZE - 1, x + 1) && same; i++) {
                            same = r.object[j][i] == r.object[y][x] && r.litState[j][i] == r.litState[y][x];
                        }
                    }
                    r.interior[y][x] = same;
                    if (same && r.litState[y][x]) {
                        r.lit++;
                    } else if (same) {
                        r.shadowed++;
                    }
                }
            }
            return r;
        }

        private static boolean segmentMeetsSphere(Vec3 from, Vec3 to, Vec3 center, double radius) {
            Vec3 u = to.minus(from);
            double tau = Math.max(0, Math.min(1, center.minus(from).dot(u) / u.dot(u)));
            return from.plus(u.times(tau)).minus(center).length() < radius;
        }
    }
}

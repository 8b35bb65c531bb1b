package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Shape;
import studio.engine.geometry.Sphere;
import studio.engine.light.PointLight;
import studio.engine.material.Fresnel;
import studio.engine.material.Material;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/**
 * Shading against values worked out by hand, one ray through the {@link Integrator}. Colours, coefficients and
 * intensities are chosen as short binary fractions so the expected sums are exact.
 */
class ShadingTest {

    private static final Vec3 UP = new Vec3(0, 1, 0);
    private static final Plane FLOOR = new Plane(Vec3.ZERO, UP);
    /** Straight down onto the floor at the origin, from height 1. */
    private static final Ray DOWN = new Ray(0, 1, 0, 0, -1, 0);
    private static final Rgb COLOR = new Rgb(0.5, 0.25, 1);
    private static final Rgb LIGHT_COLOR = new Rgb(0.75, 1, 0.5);
    private static final Rgb BACKGROUND = new Rgb(0.75, 0.5, 0.25);
    private static final double KD = 0.5, INTENSITY = 2, AMBIENT = 0.25;
    private static final Material CHALK = MaterialDefaults.of(MaterialKind.CHALK, COLOR, KD, null, null, null, null);

    @Test
    void chalkPlaneLitHeadOnGivesAmbientPlusDiffuseTimesIntensityTimesLightColour() {
        Rgb c = trace(List.of(object(FLOOR, CHALK)), List.of(light(new Vec3(0, 5, 0), false)), DOWN, 1);

        assertRgb(new Rgb(
                AMBIENT * KD * 0.5 + KD * 0.5 * INTENSITY * 0.75,
                AMBIENT * KD * 0.25 + KD * 0.25 * INTENSITY * 1,
                AMBIENT * KD * 1 + KD * 1 * INTENSITY * 0.5), c, 0.0);
    }

    @Test
    void chalkPlaneWithoutFalloffIsEquallyBrightAtAnyLightDistance() {
        Rgb near = trace(List.of(object(FLOOR, CHALK)), List.of(light(new Vec3(0, 2, 0), false)), DOWN, 1);
        Rgb far = trace(List.of(object(FLOOR, CHALK)), List.of(light(new Vec3(0, 2e6, 0), false)), DOWN, 1);

        assertRgb(near, far, 0.0);
    }

    @Test
    void chalkPlaneLitObliquelyFollowsLambertsCosine() {
        // light at (3, 4, 0) from the origin: cos = 4/5
        Rgb c = trace(List.of(object(FLOOR, CHALK)), List.of(light(new Vec3(3, 4, 0), false)), DOWN, 1);

        assertRgb(add(ambientOnly(), diffuse(0.8)), c, 1e-15);
    }

    @Test
    void lightFalloffDividesByTheDistanceSquared() {
        Rgb at2 = trace(List.of(object(FLOOR, CHALK)), List.of(light(new Vec3(0, 2, 0), true)), DOWN, 1);
        Rgb at3 = trace(List.of(object(FLOOR, CHALK)), List.of(light(new Vec3(0, 3, 0), true)), DOWN, 1);

        assertRgb(add(ambientOnly(), diffuse(1.0 / 4)), at2, 0.0);
        assertRgb(add(ambientOnly(), diffuse(1.0 / 9)), at3, 1e-15);
    }

    @Test
    void lightBehindTheSurfaceContributesNothing() {
        Rgb c = trace(List.of(object(FLOOR, CHALK)), List.of(light(new Vec3(0, -5, 0), false)), DOWN, 1);

        assertRgb(ambientOnly(), c, 0.0);
    }

    @Test
    void planeSeenFromBelowIsLitFromBelowOnly() {
        Ray up = new Ray(0, -1, 0, 0, 1, 0);

        Rgb fromAbove = trace(List.of(object(FLOOR, CHALK)), List.of(light(new Vec3(0, 5, 0), false)), up, 1);
        Rgb fromBelow = trace(List.of(object(FLOOR, CHALK)), List.of(light(new Vec3(0, -5, 0), false)), up, 1);

        assertRgb(ambientOnly(), fromAbove, 0.0);
        assertRgb(add(ambientOnly(), diffuse(1)), fromBelow, 0.0);
    }

    @Test
    void opaqueSphereBetweenPointAndLightLeavesOnlyAmbient() {
        Material black = MaterialDefaults.of(MaterialKind.CHALK, Rgb.BLACK);
        Rgb shadowed = trace(List.of(object(FLOOR, CHALK), object(new Sphere(new Vec3(0, 2.5, 0), 1), black)),
                List.of(light(new Vec3(0, 5, 0), false)), new Ray(0, 0.5, 0, 0, -1, 0), 1);
        Rgb beside = trace(List.of(object(FLOOR, CHALK), object(new Sphere(new Vec3(3, 2.5, 0), 1), black)),
                List.of(light(new Vec3(0, 5, 0), false)), new Ray(0, 0.5, 0, 0, -1, 0), 1);
        Rgb beyondLight = trace(List.of(object(FLOOR, CHALK), object(new Sphere(new Vec3(0, 7, 0), 1), black)),
                List.of(light(new Vec3(0, 5, 0), false)), new Ray(0, 0.5, 0, 0, -1, 0), 1);

        assertRgb(ambientOnly(), shadowed, 0.0);
        assertRgb(add(ambientOnly(), diffuse(1)), beside, 0.0);
        assertRgb(add(ambientOnly(), diffuse(1)), beyondLight, 0.0);
    }

    @Test
    void shadowOfOneLightKeepsTheOtherLightsContribution() {
        Material black = MaterialDefaults.of(MaterialKind.CHALK, Rgb.BLACK);
        Rgb c = trace(List.of(object(FLOOR, CHALK), object(new Sphere(new Vec3(0, 2.5, 0), 1), black)),
                List.of(light(new Vec3(0, 5, 0), false), light(new Vec3(3, 4, 0), false)),
                new Ray(0, 0.5, 0, 0, -1, 0), 1);

        assertRgb(add(ambientOnly(), diffuse(0.8)), c, 1e-15);
    }

    @Test
    void aLightTooFaintToShowIsNotLookedForAndOneJustBrighterIs() {
        // the light's unshadowed share: KD * 1 (the colour's largest channel) * intensity * 1 (the light colour's)
        double faint = 1.5 * Integrator.NEGLIGIBLE_LIGHT, visible = 2.5 * Integrator.NEGLIGIBLE_LIGHT;
        Camera camera = new Camera(new Vec3(0, 1, 5), Vec3.ZERO, UP, 45);
        for (double intensity : new double[] {faint, visible}) {
            Scene scene = new Scene(camera, List.of(object(FLOOR, CHALK)),
                    List.of(new PointLight(new Vec3(0, 5, 0), LIGHT_COLOR, intensity, false)), BACKGROUND, AMBIENT);
            Integrator integrator = new Integrator(scene, 1, 0);

            Rgb c = Radiance.of(integrator, DOWN);

            boolean shows = intensity == visible;
            assertEquals(shows ? 2 : 1, integrator.rays, "rays traced: the camera ray, and a shadow ray if the light shows");
            assertRgb(shows ? add(ambientOnly(), COLOR.times(KD).times(LIGHT_COLOR.times(intensity))) : ambientOnly(), c, 0.0);
        }
    }

    @Test
    void glassSphereCastsALighterShadowTintedByTheGlass() {
        // The shadow ray crosses the glass along its axis: each crossing at normal incidence keeps 1 - 0.04.
        Rgb tint = new Rgb(1, 0.5, 0.25);
        Material glass = MaterialDefaults.of(MaterialKind.GLASS, tint);

        Rgb c = trace(List.of(object(FLOOR, CHALK), object(new Sphere(new Vec3(0, 2, 0), 1), glass)),
                List.of(light(new Vec3(0, 5, 0), false)), new Ray(0, 0.5, 0, 0, -1, 0), 1);

        double through = (1 - 0.04) * (1 - 0.04);
        assertRgb(add(ambientOnly(), diffuse(through).times(tint)), c, 1e-15);
    }

    @Test
    void flatMaterialReturnsItsColourIgnoringLightsAndAmbient() {
        Rgb c = trace(List.of(object(FLOOR, MaterialDefaults.of(MaterialKind.FLAT, COLOR))),
                List.of(light(new Vec3(0, 5, 0), false)), DOWN, 3);

        assertRgb(COLOR, c, 0.0);
    }

    @Test
    void missReturnsTheBackground() {
        Rgb c = trace(List.of(object(FLOOR, CHALK)), List.of(light(new Vec3(0, 5, 0), false)),
                new Ray(0, 1, 0, 0, 1, 0), 3);

        assertRgb(BACKGROUND, c, 0.0);
    }

    @Test
    void mirrorReturnsItsTintTimesTheBackgroundItReflects() {
        Material mirror = MaterialDefaults.of(MaterialKind.MIRROR, COLOR);

        Rgb c = trace(List.of(object(FLOOR, mirror)), List.of(light(new Vec3(0, 5, 0), false)), DOWN, 3);

        assertRgb(new Rgb(0.5 * 0.75, 0.25 * 0.5, 1 * 0.25), c, 0.0);
    }

    @Test
    void mirrorAt45DegreesReturnsItsTintTimesTheObjectInTheMirrorDirection() {
        // From (-2,2,0) along (1,-1,0) to the origin; the reflection goes along (1,1,0) to a flat green sphere.
        Material mirror = MaterialDefaults.of(MaterialKind.MIRROR, COLOR);
        Material green = MaterialDefaults.of(MaterialKind.FLAT, new Rgb(0, 1, 0));
        List<SceneObject> objects = List.of(object(FLOOR, mirror), object(new Sphere(new Vec3(4, 4, 0), 1), green));

        Rgb c = trace(objects, List.of(), new Ray(-2, 2, 0, 1, -1, 0), 3);
        Rgb noBounce = trace(objects, List.of(), new Ray(-2, 2, 0, 1, -1, 0), 0);

        assertRgb(new Rgb(0, 0.25, 0), c, 0.0);
        assertRgb(Rgb.BLACK, noBounce, 0.0);
    }

    @Test
    void glassAtNormalIncidenceReflectsTheFresnelFractionAndTransmitsTheRest() {
        // Flat red above (what the reflection sees), flat green below (what the transmission sees).
        Material glass = MaterialDefaults.of(MaterialKind.GLASS, Rgb.WHITE);
        List<SceneObject> objects = List.of(object(FLOOR, glass),
                object(new Plane(new Vec3(0, 2, 0), UP), MaterialDefaults.of(MaterialKind.FLAT, new Rgb(1, 0, 0))),
                object(new Plane(new Vec3(0, -2, 0), UP), MaterialDefaults.of(MaterialKind.FLAT, new Rgb(0, 1, 0))));

        Rgb c = trace(objects, List.of(), DOWN, 3);

        double r = (1.5 - 1) / (1.5 + 1);
        assertEquals(r * r, c.r(), 1e-15, "reflected fraction ((n-1)/(n+1))^2");
        assertEquals(1 - r * r, c.g(), 1e-15, "transmitted fraction");
        assertEquals(1.0, c.r() + c.g(), 1e-15, "R + T = 1");
        assertEquals(0.0, c.b(), 0.0);
    }

    @Test
    void tintedDenseGlassTintsOnlyTheTransmittedLight() {
        Material glass = MaterialDefaults.of(MaterialKind.GLASS, new Rgb(1, 0.5, 1), null, null, null, null, 2.4);
        List<SceneObject> objects = List.of(object(FLOOR, glass),
                object(new Plane(new Vec3(0, 2, 0), UP), MaterialDefaults.of(MaterialKind.FLAT, new Rgb(1, 0, 0))),
                object(new Plane(new Vec3(0, -2, 0), UP), MaterialDefaults.of(MaterialKind.FLAT, new Rgb(0, 1, 0))));

        Rgb c = trace(objects, List.of(), DOWN, 3);

        double r = (2.4 - 1) / (2.4 + 1);
        assertEquals(r * r, c.r(), 1e-15);
        assertEquals(0.5 * (1 - r * r), c.g(), 1e-15);
    }

    @Test
    void plasticHighlightInTheMirrorDirectionAddsSpecularTimesLightColour() {
        // Eye ray from (-1,1,0) along (1,-1,0) hits the origin; light at (3,3,0) lies in the mirror direction,
        // so the half vector is the normal and the highlight is exactly ks * light colour * intensity.
        double ks = 0.25;
        Material plastic = MaterialDefaults.of(MaterialKind.PLASTIC, COLOR, KD, ks, 60.0, null, null);
        Material matte = MaterialDefaults.of(MaterialKind.PLASTIC, COLOR, KD, 0.0, 60.0, null, null);
        Ray eye = new Ray(-1, 1, 0, 1, -1, 0);
        List<PointLight> lights = List.of(light(new Vec3(3, 3, 0), false));

        Rgb shiny = trace(List.of(object(FLOOR, plastic)), lights, eye, 1);
        Rgb dull = trace(List.of(object(FLOOR, matte)), lights, eye, 1);

        double cos = Math.sqrt(0.5);
        assertRgb(add(ambientOnly(), diffuse(cos)), dull, 1e-15);
        assertRgb(LIGHT_COLOR.times(INTENSITY * ks), new Rgb(shiny.r() - dull.r(), shiny.g() - dull.g(),
                shiny.b() - dull.b()), 1e-15);
    }

    @Test
    void plasticHighlightFadesAwayFromTheMirrorDirection() {
        Material plastic = MaterialDefaults.of(MaterialKind.PLASTIC, COLOR, 0.0, 0.25, 60.0, null, null);
        Ray eye = new Ray(-1, 1, 0, 1, -1, 0);

        double mirror = trace(List.of(object(FLOOR, plastic)), List.of(light(new Vec3(3, 3, 0), false)), eye, 1).g();
        double off = trace(List.of(object(FLOOR, plastic)), List.of(light(new Vec3(3, 3, 1), false)), eye, 1).g();

        assertEquals(0.25 * INTENSITY, mirror, 1e-15);
        assertTrue(off < 0.5 * mirror, "off-mirror highlight " + off);
    }

    @Test
    void metalHighlightIsTintedByTheMetalsColour() {
        Material metal = MaterialDefaults.of(MaterialKind.METAL, COLOR, 0.0, 0.5, 100.0, 0.0, null);

        Rgb c = trace(List.of(object(FLOOR, metal)), List.of(light(new Vec3(3, 3, 0), false)),
                new Ray(-1, 1, 0, 1, -1, 0), 1);

        assertRgb(COLOR.times(LIGHT_COLOR).times(0.5 * INTENSITY), c, 1e-15);
    }

    @Test
    void fresnelAtNormalIncidenceMatchesTheClosedForm() {
        for (double n : new double[] {1.33, 1.5, 2.4}) {
            double r = (n - 1) / (n + 1);
            assertEquals(r * r, Fresnel.reflectance(1, 1, n), 1e-15);
            assertEquals(r * r, Fresnel.reflectance(1, n, 1), 1e-15);
        }
    }

    // --- helpers ---------------------------------------------------------------------------------------------

    private static Rgb trace(List<SceneObject> objects, List<PointLight> lights, Ray ray, int maxDepth) {
        Camera camera = new Camera(new Vec3(0, 1, 5), Vec3.ZERO, UP, 45);
        Scene scene = new Scene(camera, objects, lights, BACKGROUND, AMBIENT);
        return Radiance.of(new Integrator(scene, maxDepth, 0), ray);
    }

    private static SceneObject object(Shape shape, Material material) {
        return new SceneObject(shape, material);
    }

    private static PointLight light(Vec3 position, boolean falloff) {
        return new PointLight(position, LIGHT_COLOR, INTENSITY, falloff);
    }

    /** ambient * diffuse * colour. */
    private static Rgb ambientOnly() {
        return COLOR.times(KD).times(AMBIENT);
    }

    /** diffuse * colour * intensity * light colour, times a cosine or fall-off factor. */
    private static Rgb diffuse(double factor) {
        return COLOR.times(KD).times(LIGHT_COLOR.times(INTENSITY)).times(factor);
    }

    private static Rgb add(Rgb a, Rgb b) {
        return a.plus(b);
    }

    private static void assertRgb(Rgb expected, Rgb actual, double tolerance) {
        assertEquals(expected.r(), actual.r(), tolerance, () -> "red of " + actual + ", expected " + expected);
        assertEquals(expected.g(), actual.g(), tolerance, () -> "green of " + actual + ", expected " + expected);
        assertEquals(expected.b(), actual.b(), tolerance, () -> "blue of " + actual + ", expected " + expected);
    }
}

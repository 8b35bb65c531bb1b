package studio.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;

import studio.engine.mesh.MeshData;

class PovraySceneTest {

    static final String STILL_LIFE_LIKE = """
            { "name": "t", "camera": { "position": [4, 3, 6], "lookAt": [0, 0.7, 0], "up": [0, 1, 0], "fov": 40 },
              "background": "#000000", "ambient": 0.1, "render": { "maxDepth": 5 },
              "lights": [ { "type": "point", "position": [-3, 6, 4], "intensity": 0.5 },
                          { "type": "point", "position": [1, 2, 3], "falloff": true } ],
              "objects": [
                { "type": "box", "center": [1, 2, 3], "size": [2, 1, 0.5], "rotation": [10, 20, 30],
                  "material": { "type": "plastic", "color": "#ffffff", "shininess": 50 } },
                { "type": "plane", "point": [0, 2, 0], "normal": [0, 3, 0] },
                { "type": "sphere", "material": { "type": "glass", "color": "#ffffff", "ior": 1.4 } } ] }
            """;

    private static String sdl() {
        return PovrayScene.of(ResolvedScene.of(TestRenders.read(STILL_LIFE_LIKE), 800, 600), "t");
    }

    @Test
    void cameraIsRightHandedWithTheHorizontalAngle() {
        String sdl = sdl();
        assertTrue(sdl.contains("right -x*1.33333333333333"), sdl);
        assertTrue(sdl.contains("angle 51.7740087592426"), sdl);
        assertTrue(sdl.contains("location <4, 3, 6>") && sdl.contains("look_at <0, 0.7, 0>")
                && sdl.contains("sky <0, 1, 0>"), sdl);
        // sky before look_at: POV-Ray applies look_at with the sky it has read so far
        assertTrue(sdl.indexOf("sky") < sdl.indexOf("look_at"));
        assertTrue(sdl.indexOf("right") < sdl.indexOf("angle"), "angle is taken relative to the right vector");
    }

    @Test
    void shadesLinearlyAndTracesAsDeepAsOurs() {
        String sdl = sdl();
        assertTrue(sdl.contains("assumed_gamma 1.0"));
        assertTrue(sdl.contains("max_trace_level 6"), "POV-Ray counts the camera ray as level 1");
    }

    @Test
    void boxRotatesAboutZThenYThenX() {
        String sdl = sdl();
        assertTrue(sdl.contains("box { <-1, -0.5, -0.25>, <1, 0.5, 0.25> rotate z*30 rotate y*20 rotate x*10 "
                + "translate <1, 2, 3>"), sdl);
    }

    @Test
    void planeHasAUnitNormalAndItsDistanceFromTheOrigin() {
        assertTrue(sdl().contains("plane { <0, 1, 0>, 2"), sdl());
    }

    @Test
    void lightsWithoutFalloffKeepTheirIntensityAndWithFalloffFadeAsTheInverseSquare() {
        String sdl = sdl();
        assertTrue(sdl.contains("light_source { <-3, 6, 4> color rgb <0.5, 0.5, 0.5> }"), sdl);
        Matcher m = Pattern.compile("light_source \\{ <1, 2, 3> color rgb <([0-9.]+), [^>]*> fade_distance ([0-9.]+) "
                + "fade_power 2 }").matcher(sdl);
        assertTrue(m.find(), sdl);
        double color = Double.parseDouble(m.group(1)), f = Double.parseDouble(m.group(2));
        for (double d : new double[] {0.1, 1, 3.7, 100}) {
            // POV-Ray: colour * 2 / (1 + (d / fade_distance)^fade_power)
            double povray = color * 2 / (1 + Math.pow(d / f, 2));
            assertEquals(1 / (d * d), povray, 1e-4 / (d * d), "d=" + d);
        }
    }

    @Test
    void finishesFollowOurCoefficients() {
        String sdl = sdl();
        // plastic: ambient = diffuse 0.8 x scene ambient 0.1, Blinn highlight roughness = 1 / shininess
        assertTrue(sdl.contains("finish { ambient 0.08 diffuse 0.8 specular 0.5 roughness 0.02 }"), sdl);
        // the plane is default chalk
        assertTrue(sdl.contains("finish { ambient 0.09 diffuse 0.9 }"), sdl);
    }

    @Test
    void glassFiltersWithFresnelReflectionAndAHighlightOnlyOutside() {
        String sdl = sdl();
        assertTrue(sdl.contains("pigment { rgbf <1, 1, 1, 1> }"), sdl);
        assertTrue(sdl.contains("reflection { 0, 1 fresnel on } conserve_energy"), sdl);
        assertTrue(sdl.contains("interior { ior 1.4 }"), sdl);
        int inside = sdl.indexOf("interior_texture");
        assertTrue(inside > 0);
        String interiorTexture = sdl.substring(inside, sdl.indexOf("\n", inside));
        assertFalse(interiorTexture.contains("specular"), interiorTexture);
        assertFalse(sdl.contains("no_shadow"), "our glass casts a (light) shadow");
    }

    @Test
    void tintedGlassFiltersWithTheSquareRootOfItsColourAtEachOfItsTwoSurfaces() {
        String sdl = PovrayScene.material(studio.engine.material.MaterialDefaults.of(
                studio.engine.material.MaterialKind.GLASS, new studio.engine.math.Rgb(0.25, 0.64, 1)), 0.1);
        assertTrue(sdl.contains("rgbf <0.5, 0.8, 1, 1>"), sdl);
    }

    @Test
    void meshIsAMesh2WithAsManyVerticesNormalsAndFacesAsGiven() {
        MeshData mesh = new MeshData(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, new int[] {0, 1, 2, 2, 1, 3},
                new double[] {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
        StringBuilder sdl = new StringBuilder();
        PovrayScene.mesh(sdl, mesh);
        String text = sdl.toString();
        assertTrue(text.startsWith("mesh2 {\n  vertex_vectors { 4,\n    <0,0,0>, <1,0,0>, <0,1,0>, <1,1,0> }"), text);
        assertTrue(text.contains("normal_vectors { 4,\n    <0,0,1>, <0,0,1>, <0,0,1>, <0,0,1> }"), text);
        assertTrue(text.endsWith("face_indices { 2,\n    <0,1,2>, <2,1,3> }"), text);

        StringBuilder flat = new StringBuilder();
        PovrayScene.mesh(flat, new MeshData(mesh.positions(), mesh.indices(), null));
        assertFalse(flat.toString().contains("normal_vectors"), flat.toString());
    }

    @Test
    void meshIsScaledThenRotatedAsABoxThenMoved() {
        String json = """
                { "objects": [ { "type": "mesh", "obj": "v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 3\\n",
                                 "position": [1, 2, 3], "scale": 0.5, "rotation": [10, 20, 30] } ] }
                """;
        String sdl = PovrayScene.of(ResolvedScene.of(TestRenders.read(json), 80, 60), "t");
        assertTrue(sdl.contains("face_indices { 1,\n    <0,1,2> }\n  scale 0.5 rotate z*30 rotate y*20 rotate x*10 "
                + "translate <1, 2, 3>\n  texture"), sdl);
    }

    @Test
    void numbersArePlainDecimals() {
        assertEquals("0.00001", Sdl.num(1e-5));
        assertEquals("0", Sdl.num(-0.0));
        assertEquals("-2", Sdl.num(-2));
        assertEquals("123456789012", Sdl.num(123456789012.0));
        assertEquals("0.1", Sdl.num(0.1));
        assertEquals("0.08", Sdl.num(0.8 * 0.1));
        assertEquals("0.333333333333333", Sdl.num(1.0 / 3));
    }

    @Test
    void softLightsAreAreaLightsSampledAsAskedAndSeenThroughLooksLike() {
        String json = """
                { "lights": [ { "type": "point", "position": [0, 4, 0], "radius": 0.5, "intensity": 2 },
                              { "type": "area", "position": [1, 3, 0], "size": [2, 0.5], "lookAt": [1, 0, 0] } ],
                  "objects": [] }
                """;
        ResolvedScene scene = ResolvedScene.of(TestRenders.read(json), 80, 60);
        String plain = PovrayScene.of(scene, "t", new PovrayScene.AreaSampling(4, false, false));
        String both = PovrayScene.of(scene, "t", new PovrayScene.AreaSampling(16, true, true));

        // the sphere: a disc of its diameter, turned to each point it lights
        assertTrue(plain.contains("light_source { <0, 4, 0> color rgb <2, 2, 2>\n  area_light <1, 0, 0>, <0, 0, 1>, 4, 4"
                + " circular orient\n  looks_like { sphere { <0, 0, 0>, 0.5 "), plain);
        // the rectangle facing down: width along x, height along z, its two edges as the axes
        assertTrue(plain.contains("area_light <2, 0, 0>, <0, 0, -0.5>, 4, 4\n  looks_like { union { triangle"), plain);
        assertFalse(plain.contains("adaptive") || plain.contains("jitter"), plain);
        assertTrue(both.contains(", 16, 16 adaptive 1 jitter circular orient"), both);
        assertTrue(both.contains("emission 1"), both);
        assertFalse(sdl().contains("area_light"), "point lights stay points");
    }
}

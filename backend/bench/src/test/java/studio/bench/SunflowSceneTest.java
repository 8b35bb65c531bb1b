package studio.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class SunflowSceneTest {

    /** Where Sunflow's pinhole sends pixel i's sample (x = i + 1/2), as its PinholeLens.getRay does. */
    static double sunflowX(double[] lens, int i, int width) {
        double au = Math.tan(Math.toRadians(lens[0] / 2));
        return lens[2] - au + 2 * au * (i + 0.5) / (width - 1);
    }

    /** ... and row j (counted from the top; Sunflow samples y = H - j - 1/2). */
    static double sunflowY(double[] lens, int j, int height) {
        double av = Math.tan(Math.toRadians(lens[0] / 2)) / lens[1];
        return lens[3] - av + 2 * av * (height - j - 0.5) / (height - 1);
    }

    @Test
    void lensSendsEveryPixelCentreWhereOursDoes() {
        int w = 800, h = 600;
        double vfov = 40;
        double tanV = Math.tan(Math.toRadians(vfov / 2)), tanH = tanV * w / h;
        double[] lens = SunflowScene.lens(vfov, w, h);
        for (int i : new int[] {0, 1, 399, 400, 798, 799}) {
            assertEquals((2 * (i + 0.5) / w - 1) * tanH, sunflowX(lens, i, w), 1e-12, "column " + i);
        }
        for (int j : new int[] {0, 1, 299, 300, 599}) {
            assertEquals((1 - 2 * (j + 0.5) / h) * tanV, sunflowY(lens, j, h), 1e-12, "row " + j);
        }
    }

    @Test
    void scriptBuildsSpheresAsInstancesOfOneUnitSphere() {
        String json = """
                { "objects": [ { "type": "sphere", "center": [1, 2, 3], "radius": 0.5 },
                               { "type": "sphere", "center": [0, 0, 0], "radius": 2 },
                               { "type": "plane" } ] }
                """;
        String script = SunflowScene.of(ResolvedScene.of(TestRenders.read(json), 80, 60), 2, 2).text();
        assertEquals(1, script.split("geometry sphere sphere", -1).length - 1, script);
        assertTrue(script.contains("param transform matrix 0.5 0 0 1 0 0.5 0 2 0 0 0.5 3 0 0 0 1\n"), script);
        assertTrue(script.contains("param aa.min int 2\nparam aa.max int 2\n"), script);
        assertTrue(script.contains("param threads int 2\n"), script);
        assertTrue(script.contains("param center point 0 0 0\nparam normal vector 0 1 0\n"), script);
        // default chalk: diffuse = colour x 0.9, shared by all three objects
        assertEquals(1, script.split("shader shader0 diffuse", -1).length - 1, script);
    }

    @Test
    void aaLevelsAreFourToTheSamples() {
        assertEquals(0, Renderers.sunflowAaLevel(1));
        assertEquals(1, Renderers.sunflowAaLevel(4));
        assertEquals(2, Renderers.sunflowAaLevel(16));
        assertEquals(3, Renderers.sunflowAaLevel(64));
        assertThrows(IllegalArgumentException.class, () -> Renderers.sunflowAaLevel(9));
        assertEquals(4, Renderers.squareRoot(16));
        assertThrows(IllegalArgumentException.class, () -> Renderers.squareRoot(8));
    }

    @Test
    void scriptWordsMayNotContainSpaces() {
        assertThrows(IllegalArgumentException.class, () -> new SunflowScript().param("a b", 1));
    }
}

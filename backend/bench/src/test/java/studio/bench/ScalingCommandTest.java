package studio.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import studio.engine.geometry.Sphere;
import studio.engine.scene.SceneObject;

class ScalingCommandTest {

    @Test
    void countsArePowersOfTenUpToTheMaximum() {
        assertEquals(List.of(10, 100, 1000), ScalingCommand.counts(1000));
        assertEquals(List.of(10, 100, 1000), ScalingCommand.counts(9999));
        assertEquals(List.of(10, 100, 1_000, 10_000, 100_000, 1_000_000), ScalingCommand.counts(1_000_000));
    }

    @Test
    void spheresShrinkSoThatTheyCoverAsMuchAtEveryCount() {
        for (int n : new int[] {10, 1000, 100_000}) {
            List<SceneObject> spheres = ScalingScenes.spheres(n);
            assertEquals(n, spheres.size());
            double r = ((Sphere) spheres.get(0).shape()).radius();
            // n pi r^2 is the box's front face, 5 x 3
            assertEquals(15, n * Math.PI * r * r, 1e-9);
        }
        assertEquals(ScalingScenes.spheres(50), ScalingScenes.spheres(50), "fixed seed");
    }

    @Test
    void knotsHaveAboutTheAskedNumberOfTriangles() {
        assertEquals(18, ScalingScenes.knot(10).triangleCount());
        for (int n : new int[] {100, 1000, 10_000, 100_000, 1_000_000}) {
            int[] t = ScalingScenes.knotTessellation(n);
            int triangles = 2 * t[0] * t[1];
            assertTrue(Math.abs(triangles - n) <= 0.05 * n, n + ": " + triangles);
        }
        assertEquals(1_000_000, 2 * ScalingScenes.knotTessellation(1_000_000)[0] * ScalingScenes.knotTessellation(1_000_000)[1]);
    }

    /** A tiny run of the whole command: the table, the CSV, the chart and the OBJ-to-image line. */
    @Test
    void writesCsvAndChart(@TempDir Path dir) throws Exception {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int code = ScalingCommand.run(new String[] {"--max", "100", "--runs", "1", "--width", "40", "--height", "30",
                "--out", dir.toString(), "--work", dir.resolve("work").toString()},
                new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(0, code, err.toString(StandardCharsets.UTF_8));
        List<String> csv = Files.readAllLines(dir.resolve("scaling.csv"));
        assertEquals("series,count,build_ms,bvh_ms,render_ms,render_runs_ms,rays,rays_per_s", csv.get(0));
        assertEquals(5, csv.size(), String.join("\n", csv));
        assertTrue(csv.get(1).startsWith("spheres,10,"), csv.get(1));
        assertTrue(csv.get(4).startsWith("triangles,102,"), csv.get(4));
        assertEquals(760, ImageIO.read(dir.resolve("scaling.png").toFile()).getWidth());
        String text = out.toString(StandardCharsets.UTF_8);
        assertTrue(text.contains("OBJ to image, 102 triangles"), text);
        assertTrue(Files.exists(dir.resolve("work").resolve("torus-knot-102.obj")));
    }

    @Test
    void rejectsBadArguments() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream e = new PrintStream(err, true, StandardCharsets.UTF_8);
        assertEquals(ScalingCommand.INVALID, ScalingCommand.run(new String[] {"--max", "5"}, System.out, e));
        assertEquals(ScalingCommand.INVALID, ScalingCommand.run(new String[] {"--bogus"}, System.out, e));
    }
}

package studio.bench.kernel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.TriangleMesh;
import studio.engine.light.PointLight;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.mesh.MeshData;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

class KernelGeometryTest {

    /** What Embree is given for a box must be the box: 12 triangles, wound outward, on the same surface. */
    @Test
    void aBoxIsWrittenAsTwelveOutwardTrianglesOnItsSurface(@TempDir Path dir) throws Exception {
        Box box = new Box(new Vec3(0.3, 0.6, -0.2), new Vec3(1.2, 0.7, 0.4), new Vec3(30, 45, 60));
        Scene scene = new Scene(new Camera(new Vec3(0, 1, 5), Vec3.ZERO, new Vec3(0, 1, 0), 40),
                List.of(new SceneObject(box, MaterialDefaults.of(MaterialKind.CHALK, Rgb.WHITE))),
                List.of(new PointLight(new Vec3(2, 5, 3), Rgb.WHITE, 1, false)), Rgb.BLACK, 0);
        Path file = dir.resolve("box.kernel");
        KernelGeometry.write(scene, 40, 64, 48, file);

        List<String> lines = Files.readAllLines(file);
        assertTrue(lines.contains("light 2.0 5.0 3.0"), String.join("\n", lines));
        int at = lines.indexOf("triangles 8 12");
        assertTrue(at > 0, String.join("\n", lines));
        double[] positions = lines.subList(at + 1, at + 9).stream()
                .flatMap(l -> Arrays.stream(l.split(" "))).mapToDouble(Double::parseDouble).toArray();
        int[] indices = lines.subList(at + 9, at + 21).stream()
                .flatMap(l -> Arrays.stream(l.split(" "))).mapToInt(Integer::parseInt).toArray();
        TriangleMesh triangles = new TriangleMesh(new MeshData(positions, indices, null));

        Random random = new Random(7);
        Hit onBox = new Hit(), onTriangles = new Hit();
        int hits = 0;
        for (int i = 0; i < 2000; i++) {
            Vec3 from = new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalized().times(4);
            Vec3 to = new Vec3(random.nextDouble() - 0.5, random.nextDouble() - 0.5, random.nextDouble() - 0.5)
                    .times(1.6).plus(box.center());
            Ray ray = new Ray(from, to.minus(from).normalized());
            boolean hit = box.intersect(ray, Double.POSITIVE_INFINITY, onBox);
            assertEquals(hit, triangles.intersect(new Ray(from, ray.direction()), Double.POSITIVE_INFINITY, onTriangles),
                    "ray " + i);
            if (hit) {
                hits++;
                assertEquals(onBox.t, onTriangles.t, 1e-9, "ray " + i);
                // the triangle's own normal (by its winding) is the box face's outward normal
                assertEquals(1, onBox.normal().dot(new Vec3(onTriangles.gx, onTriangles.gy, onTriangles.gz)), 1e-9);
            }
        }
        assertTrue(hits > 500 && hits < 2000, hits + " of 2000 rays hit");
    }

    /** A tiny run of the command: its counts are the mask's, and every frame counted the same. */
    @Test
    void countsAgreeWithTheMaskItWrites(@TempDir Path dir) throws Exception {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int code = KernelCommand.run(new String[] {"--scenes", "still-life", "--scenes-dir", scenes().toString(),
                        "--width", "64", "--height", "48", "--frames", "2", "--warm-up", "1", "--work", dir.toString()},
                new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(0, code, err.toString(StandardCharsets.UTF_8));

        String line = out.toString(StandardCharsets.UTF_8).lines().filter(l -> l.startsWith("kernel=ours")).findFirst()
                .orElseThrow();
        byte[] pgm = Files.readAllBytes(dir.resolve("still-life.ours.pgm"));
        byte[] header = "P5\n64 48\n255\n".getBytes(StandardCharsets.US_ASCII);
        assertEquals(header.length + 64 * 48, pgm.length);
        long hits = 0, shadowed = 0;
        for (int i = header.length; i < pgm.length; i++) {
            hits += pgm[i] != PrimaryShadowRays.MISS ? 1 : 0;
            shadowed += pgm[i] == PrimaryShadowRays.SHADOWED ? 1 : 0;
        }
        assertTrue(hits > 0 && shadowed > 0 && hits > shadowed, hits + " hits, " + shadowed + " in shadow");
        assertTrue(line.contains(" primary=3072 shadow=" + hits + " hits=" + hits + " occluded=" + shadowed + " "), line);
        assertTrue(Files.readString(dir.resolve("still-life.kernel")).startsWith("# studio-bench kernel geometry"));
    }

    /** The repository's scenes folder, found from the working directory up. */
    private static Path scenes() {
        for (Path at = Path.of("").toAbsolutePath(); at != null; at = at.getParent()) {
            if (Files.isRegularFile(at.resolve("scenes").resolve("still-life.json"))) {
                return at.resolve("scenes");
            }
        }
        throw new IllegalStateException("cannot find scenes/ above " + Path.of("").toAbsolutePath());
    }
}

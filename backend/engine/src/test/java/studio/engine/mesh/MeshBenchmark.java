package studio.engine.mesh;

import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import studio.engine.camera.Camera;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.TriangleMesh;
import studio.engine.light.PointLight;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.render.RenderResult;
import studio.engine.render.RenderSettings;
import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.engine.sampler.RegularSampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/**
 * Not a test: times the mesh pipeline on a 1,000,000-triangle torus knot. Run from backend/engine:
 * <pre>
 *   java -cp target/classes:target/test-classes studio.engine.mesh.MeshBenchmark write /tmp/knot.obj
 *   java -cp target/classes:target/test-classes studio.engine.mesh.MeshBenchmark render /tmp/knot.obj
 * </pre>
 * {@code write} generates the knot and writes it as OBJ with 6 decimals; {@code render} parses it, places it
 * (vertex transform and BVH build), counts single-thread primary rays per second against it, and
 * renders it 800x600 at 1 sample per pixel on every core, printing each step's time.
 */
public final class MeshBenchmark {

    private static final int WIDTH = 800, HEIGHT = 600;

    private MeshBenchmark() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length != 2 || !(args[0].equals("write") || args[0].equals("render"))) {
            System.err.println("usage: MeshBenchmark write|render FILE.obj");
            System.exit(2);
        }
        Path file = Path.of(args[1]);
        if (args[0].equals("write")) {
            long t0 = System.nanoTime();
            MeshData knot = MeshShapes.torusKnot(2, 3, 1000, 500);
            long t1 = System.nanoTime();
            try (Writer out = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
                ObjWriter.write(knot, out, 6); // as modelling tools write OBJ
            }
            long t2 = System.nanoTime();
            System.out.printf("generated %,d triangles in %d ms, wrote %s (%,d bytes) in %d ms%n", knot.triangleCount(),
                    ms(t1 - t0), file, Files.size(file), ms(t2 - t1));
            return;
        }
        long start = System.nanoTime();
        MeshData data;
        try (Reader in = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            data = ObjReader.read(in);
        }
        long parsed = System.nanoTime();
        TriangleMesh mesh = new TriangleMesh(data, new Vec3(0, 1.2, 0), 1, new Vec3(-60, 0, 0));
        long built = System.nanoTime();
        System.out.printf("parse: %,d triangles in %d ms%n", data.triangleCount(), ms(parsed - start));
        System.out.printf("place: %d ms, of which BVH build %d ms%n", ms(built - parsed), ms(mesh.buildNanos()));

        Camera camera = new Camera(new Vec3(0, 2.5, 4.5), new Vec3(0, 1, 0), new Vec3(0, 1, 0), 45);
        Scene scene = new Scene(camera, List.of(
                new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)), MaterialDefaults.of(MaterialKind.CHALK, null)),
                new SceneObject(mesh, MaterialDefaults.of(MaterialKind.PLASTIC, new Rgb(0.8, 0.3, 0.2)))),
                List.of(new PointLight(new Vec3(3, 6, 4), Rgb.WHITE, 1, false)), new Rgb(0.1, 0.1, 0.15), 0.1);

        RenderResult result = Renderer.render(RenderRequest.of(scene, new RenderSettings(WIDTH, HEIGHT, new RegularSampler(1), 4, 0)));
        long rendered = System.nanoTime();
        System.out.printf("render: %dx%d, 1 spp, %d threads: %d ms (%,d rays, non-finite samples %d)%n", WIDTH, HEIGHT,
                Runtime.getRuntime().availableProcessors(), ms(rendered - built), result.raysTraced(),
                result.nonFiniteSamples());
        System.out.printf("parse + place + render: %d ms%n", ms(rendered - start));

        for (int round = 0; round < 3; round++) {
            primaryRays(scene, camera, round == 2);
        }
    }

    /** Single-thread primary rays per second: every pixel centre of the 800x600 view, intersect only. */
    private static void primaryRays(Scene scene, Camera camera, boolean print) {
        Ray[] rays = new Ray[WIDTH * HEIGHT];
        double aspect = (double) WIDTH / HEIGHT;
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                rays[y * WIDTH + x] = camera.ray(2 * (x + 0.5) / WIDTH - 1, 1 - 2 * (y + 0.5) / HEIGHT, aspect);
            }
        }
        Hit hit = new Hit();
        int hits = 0;
        long t0 = System.nanoTime();
        for (Ray ray : rays) {
            if (scene.intersect(ray, Double.POSITIVE_INFINITY, hit) && hit.primitive == 1) {
                hits++;
            }
        }
        long t1 = System.nanoTime();
        if (print) {
            System.out.printf("primary rays, 1 thread: %,.0f rays/s (%,d of %,d on the mesh)%n",
                    rays.length / ((t1 - t0) / 1e9), hits, rays.length);
        }
    }

    private static long ms(long nanos) {
        return nanos / 1_000_000;
    }
}

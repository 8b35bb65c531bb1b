package studio.bench;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDate;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import javax.imageio.ImageIO;

import studio.engine.geometry.TriangleMesh;
import studio.engine.image.ImageEncoder;
import studio.engine.mesh.MeshData;
import studio.engine.mesh.ObjReader;
import studio.engine.render.RenderResult;
import studio.engine.render.RenderSettings;
import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.engine.sampler.Sampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;
import studio.server.cli.Args;

/**
 * {@code studio-bench.jar scaling [--out docs/bench] [--max 1000000] [--runs 3] [--work DIR]}: render
 * time against the number of objects, in this JVM, through the engine's API ({@link ScalingScenes}):
 * 10, 100, ... up to {@code --max} spheres, and a torus knot of about as many triangles, each at
 * 800x600, one sample per pixel through the pixel centre ({@code regular}), on every core. Per count
 * it reports the build time (the median of {@value #BUILDS} builds of the Scene, which builds the BVH
 * over the objects; for the knot also of the TriangleMesh, which places the vertices and builds the
 * BVH over the triangles, whose own time is the {@code bvh_ms} column), the median render time of
 * {@code --runs} renders after one warm-up, and the rays per second at that median. Writes
 * {@code scaling.csv} and {@code scaling.png} (log-x) to {@code --out}, and each warm-up image to
 * {@code --work}.
 *
 * <p>Then the whole path of the largest mesh as the command line takes it: the knot written as an
 * OBJ file into {@code --work} (not timed), read and parsed, built, rendered once. At a million
 * triangles the target is under {@value #TARGET_SECONDS} seconds for all three.
 */
public final class ScalingCommand {

    static final int OK = 0, IO_ERROR = 1, INVALID = 2;
    static final int TARGET_SECONDS = 10;
    static final int TARGET_TRIANGLES = 1_000_000;
    static final String USAGE = "usage: java -jar studio-bench.jar scaling [--out docs/bench] [--max 1000000] "
            + "[--runs 3] [--work DIR] [--threads N (default: all cores)] [--width 800] [--height 600]";

    /** Builds per count; the median is reported. */
    static final int BUILDS = 3;

    private ScalingCommand() {
    }

    /** One measured scene: the series ("spheres" or "triangles"), objects or triangles, times in nanoseconds. */
    record Row(String series, int count, long buildNanos, long bvhNanos, long[] renderNanos, long rays) {

        long medianRenderNanos() {
            long[] sorted = renderNanos.clone();
            Arrays.sort(sorted);
            int n = sorted.length;
            return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
        }

        double raysPerSecond() {
            return rays * 1e9 / medianRenderNanos();
        }
    }

    public static int run(String[] args, PrintStream out, PrintStream err) {
        Options o = Args.options(args, Options::parse, USAGE, err);
        if (o == null) {
            return INVALID;
        }
        if (o.help) {
            out.println(USAGE);
            return OK;
        }
        System.setProperty("java.awt.headless", "true");
        RenderSettings settings = new RenderSettings(o.width, o.height, Sampler.of("regular", 1), 5, o.threads, 0L,
                RenderSettings.DEFAULT_MIN_PATH_WEIGHT, 0);
        List<Integer> counts = counts(o.max);
        String setup = String.format(Locale.ROOT, "%s, %d cores (%s %s), Java %s. %dx%d, 1 sample per pixel (regular), "
                        + "%d threads; build: median of 3, render: median of %d after 1 warm-up.", LocalDate.now(),
                Runtime.getRuntime().availableProcessors(), System.getProperty("os.name"), System.getProperty("os.arch"),
                System.getProperty("java.version"), o.width, o.height, settings.effectiveThreads(), o.runs);
        out.println(setup);

        List<Row> rows = new ArrayList<>();
        MeshData largest = null;
        try {
            Files.createDirectories(o.work);
            // class loading and a first compilation of the builders, off the clock
            ScalingScenes.scene(ScalingScenes.withGround(ScalingScenes.spheres(1000)));
            ScalingScenes.placedKnot(ScalingScenes.knot(1000));
            for (int n : counts) {
                List<SceneObject> all = ScalingScenes.withGround(ScalingScenes.spheres(n));
                Scene[] scene = new Scene[1];
                long build = medianNanos(BUILDS, () -> scene[0] = ScalingScenes.scene(all));
                rows.add(measure("spheres", n, build, -1, scene[0], settings, o.runs, o.work, err));
                out.println(line(rows.get(rows.size() - 1)));
            }
            for (int n : counts) {
                MeshData knot = ScalingScenes.knot(n);
                TriangleMesh[] mesh = new TriangleMesh[1];
                Scene[] scene = new Scene[1];
                long build = medianNanos(BUILDS, () -> {
                    mesh[0] = ScalingScenes.placedKnot(knot);
                    scene[0] = ScalingScenes.scene(ScalingScenes.withGround(List.of(ScalingScenes.knotObject(mesh[0]))));
                });
                rows.add(measure("triangles", mesh[0].triangleCount(), build, mesh[0].buildNanos(), scene[0], settings,
                        o.runs, o.work, err));
                out.println(line(rows.get(rows.size() - 1)));
                largest = knot;
            }
        } catch (IOException e) {
            err.println("error: cannot write to " + o.work + ": " + e.getMessage());
            return IO_ERROR;
        }

        try {
            Files.createDirectories(o.out);
            Files.writeString(o.out.resolve("scaling.csv"), csv(rows));
            ScalingChart.write(rows, o.out.resolve("scaling.png"));
        } catch (IOException e) {
            err.println("error: cannot write to " + o.out + ": " + e.getMessage());
            return IO_ERROR;
        }
        out.println("wrote " + o.out.resolve("scaling.csv") + " and " + o.out.resolve("scaling.png"));

        try {
            out.println(objToImage(largest, o.work, settings));
        } catch (IOException e) {
            err.println("error: " + e.getMessage());
            return IO_ERROR;
        }
        return OK;
    }

    /** 10, 100, ... up to max. */
    static List<Integer> counts(int max) {
        List<Integer> counts = new ArrayList<>();
        for (long n = 10; n <= max; n *= 10) {
            counts.add((int) n);
        }
        return counts;
    }

    /** The median wall time of {@code times} runs of {@code task}. */
    static long medianNanos(int times, Runnable task) {
        long[] t = new long[times];
        for (int i = 0; i < times; i++) {
            long start = System.nanoTime();
            task.run();
            t[i] = System.nanoTime() - start;
        }
        Arrays.sort(t);
        return times % 2 == 1 ? t[times / 2] : (t[times / 2 - 1] + t[times / 2]) / 2;
    }

    /**
     * One warm-up render (saved as {@code scaling-SERIES-COUNT.png} in {@code work}, to see that the
     * scenes look alike), then {@code runs} timed ones (wall time around Renderer.render).
     */
    static Row measure(String series, int count, long buildNanos, long bvhNanos, Scene scene, RenderSettings settings,
                       int runs, Path work, PrintStream err) throws IOException {
        RenderResult warmUp = Renderer.render(RenderRequest.of(scene, settings));
        ImageIO.write(ImageEncoder.toImage(warmUp.film()), "png", work.resolve("scaling-" + series + "-" + count + ".png")
                .toFile());
        long[] times = new long[runs];
        long rays = 0;
        for (int i = 0; i < runs; i++) {
            long start = System.nanoTime();
            RenderResult result = Renderer.render(RenderRequest.of(scene, settings));
            times[i] = System.nanoTime() - start;
            rays = result.raysTraced();
            if (result.nonFiniteSamples() > 0) {
                err.println("warning: " + series + " " + count + ": " + result.nonFiniteSamples() + " non-finite samples");
            }
        }
        return new Row(series, count, buildNanos, bvhNanos, times, rays);
    }

    /**
     * The largest knot as the command line would take it: written to an OBJ file (untimed), then
     * read and parsed ({@code Files.readString} and {@link ObjReader#parse}, as the CLI does), built
     * and rendered once.
     */
    static String objToImage(MeshData knot, Path work, RenderSettings settings) throws IOException {
        Files.createDirectories(work);
        Path obj = work.resolve("torus-knot-" + knot.triangleCount() + ".obj");
        MeshScene.writeObj(knot, obj);

        long t0 = System.nanoTime();
        MeshData parsed = ObjReader.parse(Files.readString(obj, StandardCharsets.UTF_8));
        long t1 = System.nanoTime();
        TriangleMesh mesh = ScalingScenes.placedKnot(parsed);
        Scene scene = ScalingScenes.scene(ScalingScenes.withGround(List.of(ScalingScenes.knotObject(mesh))));
        long t2 = System.nanoTime();
        Renderer.render(RenderRequest.of(scene, settings));
        long t3 = System.nanoTime();
        double total = (t3 - t0) / 1e9;
        String verdict = parsed.triangleCount() >= TARGET_TRIANGLES
                ? (total < TARGET_SECONDS ? " (target: under " + TARGET_SECONDS + " s: met)"
                        : " (target: under " + TARGET_SECONDS + " s: MISSED)")
                : " (the " + TARGET_SECONDS + " s target is for " + TARGET_TRIANGLES + " triangles: --max 1000000)";
        return String.format(Locale.ROOT, "OBJ to image, %,d triangles (%s, %.1f MB): read and parse %.0f ms, "
                        + "build %.0f ms, render %.0f ms; total %.2f s%s", parsed.triangleCount(), obj,
                Files.size(obj) / 1e6, (t1 - t0) / 1e6, (t2 - t1) / 1e6, (t3 - t2) / 1e6, total, verdict);
    }

    static String line(Row r) {
        return String.format(Locale.ROOT, "%-9s %,10d  build %9.2f ms%s  render %8.1f ms  %6.2f Mrays/s", r.series(),
                r.count(), r.buildNanos() / 1e6,
                r.bvhNanos() >= 0 ? String.format(Locale.ROOT, " (BVH %8.2f ms)", r.bvhNanos() / 1e6) : "                ",
                r.medianRenderNanos() / 1e6, r.raysPerSecond() / 1e6);
    }

    static String csv(List<Row> rows) {
        StringBuilder csv = new StringBuilder("series,count,build_ms,bvh_ms,render_ms,render_runs_ms,rays,rays_per_s\n");
        for (Row r : rows) {
            csv.append(String.format(Locale.ROOT, "%s,%d,%.3f,%s,%.1f,%s,%d,%.0f%n", r.series(), r.count(),
                    r.buildNanos() / 1e6, r.bvhNanos() >= 0 ? String.format(Locale.ROOT, "%.3f", r.bvhNanos() / 1e6) : "",
                    r.medianRenderNanos() / 1e6, Arrays.stream(r.renderNanos())
                            .mapToObj(t -> String.format(Locale.ROOT, "%.1f", t / 1e6))
                            .reduce((a, b) -> a + " " + b).orElse(""),
                    r.rays(), r.raysPerSecond()));
        }
        return csv.toString();
    }

    /** The parsed command line. */
    static final class Options {
        Path out = Path.of("docs/bench");
        Path work = Path.of(System.getProperty("java.io.tmpdir"), "studio-scaling");
        int max = 1_000_000;
        int runs = 3;
        int threads = 0;
        int width = 800, height = 600;
        boolean help;

        static Options parse(String[] args) {
            Options o = new Options();
            for (int i = 0; i < args.length; i++) {
                String a = args[i];
                switch (a) {
                    case "-h", "--help" -> o.help = true;
                    case "--out" -> o.out = Path.of(Args.value(args, ++i, a));
                    case "--work" -> o.work = Path.of(Args.value(args, ++i, a));
                    case "--max" -> o.max = Args.positive(args, ++i, a);
                    case "--runs" -> o.runs = Args.positive(args, ++i, a);
                    case "--threads" -> o.threads = Args.positive(args, ++i, a);
                    case "--width" -> o.width = Args.positive(args, ++i, a);
                    case "--height" -> o.height = Args.positive(args, ++i, a);
                    default -> throw new IllegalArgumentException("unknown argument " + a);
                }
            }
            if (o.max < 10) {
                throw new IllegalArgumentException("--max must be at least 10");
            }
            return o;
        }
    }
}

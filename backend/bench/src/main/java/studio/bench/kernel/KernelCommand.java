package studio.bench.kernel;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import studio.bench.PeersCommand;
import studio.engine.scene.Scene;
import studio.server.cli.Args;
import studio.server.scene.compiling.MeshFiles;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.format.CameraDto;
import studio.server.scene.format.InvalidSceneException;
import studio.server.scene.format.SceneDefaults;
import studio.server.scene.reading.LazyValidation;
import studio.server.scene.reading.SceneReader;

/**
 * {@code studio-bench.jar kernel [--scenes still-life,spheres-10k,mesh-100k] [--threads 1] [--frames 15]
 * [--warm-up 5] [--work DIR]}: our ray kernel's throughput, to set beside Embree's
 * ({@code backend/bench/embree/}, docs/speed.md). Each scene is compiled by the server's
 * SceneCompiler and its geometry written to {@code WORK/NAME.kernel} for embree_rays; then whole
 * 640x480 frames of {@link PrimaryShadowRays} (a camera ray a pixel, a shadow ray a hit, no
 * shading) are traced, warm-up frames for {@code --warm-up} seconds (at least 3), then
 * {@code --frames} timed ones, and each pixel's outcome is written to {@code WORK/NAME.ours.pgm}
 * to compare with Embree's. One line a scene, in the form embree_rays prints: rays counted,
 * hit and blocked counts, the first frame's wall time, and the best and median of the timed frames
 * by wall clock and by the tracing threads' CPU time ({@link KernelFrames}), in milliseconds and in
 * millions of rays (primary plus shadow) a second.
 */
public final class KernelCommand {

    static final int OK = 0, IO_ERROR = 1, INVALID = 2;
    static final List<String> SCENES = List.of("still-life", "spheres-10k", "mesh-100k");
    static final String USAGE = "usage: java -jar studio-bench.jar kernel [--scenes " + String.join(",", SCENES)
            + "] [--threads 1] [--frames 15] [--warm-up 5 (seconds)] [--width 640] [--height 480] "
            + "[--scenes-dir scenes] [--work DIR]";

    private KernelCommand() {
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
        out.printf(Locale.ROOT, "# ours: Java %s (%s), %d cores; %dx%d, %d thread(s); warm-up %d s, %d timed frames%n",
                System.getProperty("java.version"), System.getProperty("java.vm.name"),
                Runtime.getRuntime().availableProcessors(), o.width, o.height, o.threads, o.warmUpSeconds, o.frames);
        try (LazyValidation validation = new LazyValidation()) {
            Files.createDirectories(o.work);
            SceneReader reader = new SceneReader(validation);
            for (String name : o.scenes) {
                byte[] json = name.equals("still-life") ? Files.readAllBytes(o.scenesDir.resolve("still-life.json"))
                        : PeersCommand.generated(name, o.work);
                Path meshFolder = name.equals("still-life") ? o.scenesDir : o.work;
                Scene scene = SceneCompiler.standalone(validation, MeshFiles.in(meshFolder)).compile(CompileRequest.of(json)).scene();
                CameraDto camera = reader.read(json).camera();
                double fov = camera != null && camera.fov() != null ? camera.fov() : SceneDefaults.CAMERA_FOV_DEGREES;
                KernelGeometry.write(scene, fov, o.width, o.height, o.work.resolve(name + ".kernel"));

                KernelFrames frames = new KernelFrames(scene, o.width, o.height, o.threads);
                KernelFrames.Times t = frames.measure(o.warmUpSeconds * 1_000_000_000L, o.frames);
                frames.writeMask(o.work.resolve(name + ".ours.pgm"));
                out.println(line(name, o, frames, t));
            }
        } catch (IOException e) {
            err.println("error: " + e.getMessage());
            return IO_ERROR;
        } catch (InvalidSceneException | IllegalArgumentException e) {
            err.println("error: " + e.getMessage());
            return INVALID;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return IO_ERROR;
        }
        return OK;
    }

    /** The result line; embree_rays prints the same keys. Rays are primary plus shadow rays. */
    static String line(String scene, Options o, KernelFrames frames, KernelFrames.Times t) {
        long primary = (long) o.width * o.height, shadow = frames.hits(), rays = primary + shadow;
        long best = t.wall()[0], median = KernelFrames.Times.median(t.wall());
        long bestCpu = t.cpu()[0], medianCpu = KernelFrames.Times.median(t.cpu());
        return String.format(Locale.ROOT, "kernel=ours scene=%s threads=%d primary=%d shadow=%d hits=%d occluded=%d "
                        + "first_ms=%.1f best_ms=%.1f median_ms=%.1f best_cpu_ms=%.1f median_cpu_ms=%.1f "
                        + "mrays_best=%.3f mrays_median=%.3f mrays_cpu_best=%.3f mrays_cpu_median=%.3f", scene, o.threads,
                primary, shadow, frames.hits(), frames.occluded(), t.first() / 1e6, best / 1e6, median / 1e6,
                bestCpu / 1e6, medianCpu / 1e6, rays * 1e3 / best, rays * 1e3 / median, rays * 1e3 / bestCpu,
                rays * 1e3 / medianCpu);
    }

    /** The parsed command line. */
    static final class Options {
        List<String> scenes = SCENES;
        Path scenesDir = Path.of("scenes");
        Path work = Path.of(System.getProperty("java.io.tmpdir"), "studio-kernel");
        int threads = 1, frames = 15, warmUpSeconds = 5;
        int width = 640, height = 480;
        boolean help;

        static Options parse(String[] args) {
            Options o = new Options();
            for (int i = 0; i < args.length; i++) {
                String a = args[i];
                switch (a) {
                    case "-h", "--help" -> o.help = true;
                    case "--scenes" -> o.scenes = List.of(Args.value(args, ++i, a).split(","));
                    case "--scenes-dir" -> o.scenesDir = Path.of(Args.value(args, ++i, a));
                    case "--work" -> o.work = Path.of(Args.value(args, ++i, a));
                    case "--threads" -> o.threads = Args.positive(args, ++i, a);
                    case "--frames" -> o.frames = Args.positive(args, ++i, a);
                    case "--warm-up" -> o.warmUpSeconds = Args.positive(args, ++i, a);
                    case "--width" -> o.width = Args.positive(args, ++i, a);
                    case "--height" -> o.height = Args.positive(args, ++i, a);
                    default -> throw new IllegalArgumentException("unknown argument " + a);
                }
            }
            for (String s : o.scenes) {
                if (!SCENES.contains(s)) {
                    throw new IllegalArgumentException("unknown scene '" + s + "'; the scenes are " + String.join(", ", SCENES));
                }
            }
            return o;
        }
    }
}

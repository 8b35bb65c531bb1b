package studio.server.cli;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;

import studio.engine.render.RenderResult;
import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.server.render.ImageFiles;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.MeshFiles;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.format.InvalidSceneException;
import studio.server.scene.reading.LazyValidation;

/**
 * {@code studio.jar render SCENE.json -o OUT.(png|jpg) [--width W] [--height H] [--samples N]
 * [--sampler NAME] [--adaptive T] [--threads N] [--quiet]}: renders a scene file through the same validation and
 * mapping as the API, without starting the HTTP server.
 */
public final class RenderCommand {

    /** Exit codes: 0 done, 1 could not read or write a file, 2 bad arguments or an invalid scene. */
    static final int OK = 0, IO_ERROR = 1, INVALID = 2;

    static final String USAGE = "usage: java -jar studio.jar render SCENE.json [-o OUT.png|OUT.jpg] [--width W] "
            + "[--height H] [--samples N] [--sampler regular|random|jittered|multijittered|sobol] [--adaptive T] "
            + "[--threads N] [--quiet]";

    private RenderCommand() {
    }

    public static int run(String[] args, PrintStream out, PrintStream err) {
        Options options = Args.options(args, Options::parse, USAGE, err);
        if (options == null) {
            return INVALID;
        }
        if (options.help) {
            out.println(USAGE);
            return OK;
        }
        byte[] json;
        try {
            json = Files.readAllBytes(options.scene);
        } catch (NoSuchFileException e) {
            err.println("error: no such scene file: " + options.scene);
            return IO_ERROR;
        } catch (IOException e) {
            err.println("error: cannot read " + options.scene + ": " + e.getMessage());
            return IO_ERROR;
        }

        CompiledScene compiled;
        try (LazyValidation validation = new LazyValidation()) {
            SceneCompiler compiler = SceneCompiler.standalone(validation);
            compiled = compiler.compile(CompileRequest.of(json).overriding(options.overrides()).onThreads(options.threads)
                    .readingMeshesFrom(MeshFiles.in(options.scene.toAbsolutePath().getParent())));
        } catch (InvalidSceneException e) {
            err.println("error: invalid scene " + options.scene + ": " + e.getMessage());
            return INVALID;
        }

        Path output = options.output != null ? options.output : Path.of(compiled.fileName());
        String format = formatOf(output);
        if (format == null) {
            err.println("error: the output file must end in .png, .jpg or .jpeg: " + output);
            return INVALID;
        }

        ProgressBar progress = options.quiet ? null : ProgressBar.forTerminal(err);
        RenderRequest request = compiled.request();
        RenderResult result = Renderer.render(progress != null ? request.heardBy(progress::tileFinished) : request);
        if (progress != null) {
            progress.finish();
        }

        try {
            writeAtomically(output, result, format, compiled.quality());
        } catch (IOException e) {
            err.println("error: cannot write " + output + ": " + e.getMessage());
            return IO_ERROR;
        }
        if (!options.quiet) {
            int samples = compiled.settings().sampler().samplesPerPixel();
            String perPixel = compiled.settings().adaptive()
                    ? String.format(Locale.ROOT, "%.1f samples/pixel on average, at most %d",
                            result.meanSamplesPerPixel(), samples)
                    : samples + " samples/pixel";
            out.printf(Locale.ROOT, "wrote %s (%dx%d, %s, %.2f s, %.2f M rays/s)%n", output,
                    compiled.settings().width(), compiled.settings().height(), perPixel,
                    result.elapsedNanos() / 1e9, result.raysPerSecond() / 1e6);
        }
        return OK;
    }

    /** The image format an output file name asks for, or null. */
    static String formatOf(Path output) {
        String name = output.getFileName().toString().toLowerCase(Locale.ROOT);
        if (name.endsWith(".png")) {
            return "png";
        }
        if (name.endsWith(".jpg") || name.endsWith(".jpeg")) {
            return "jpg";
        }
        return null;
    }

    /** Writes beside the target and renames, so no reader ever sees half a file. */
    private static void writeAtomically(Path output, RenderResult result, String format, double quality)
            throws IOException {
        Path absolute = output.toAbsolutePath();
        // Not Files.createTempFile: its owner-only permissions would carry over to the image.
        Path temp = absolute.resolveSibling("." + absolute.getFileName() + "." + ProcessHandle.current().pid() + ".part");
        try {
            try (OutputStream stream = Files.newOutputStream(temp, StandardOpenOption.CREATE_NEW)) {
                ImageFiles.write(result.film(), format, quality, stream);
            }
            try {
                Files.move(temp, absolute, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temp, absolute, StandardCopyOption.REPLACE_EXISTING);
            }
        } finally {
            Files.deleteIfExists(temp);
        }
    }

    /** The parsed command line. */
    static final class Options {
        Path scene;
        Path output;
        Integer width, height, samples;
        String sampler;
        Double adaptive;
        int threads;
        boolean quiet, help;

        static Options parse(String[] args) {
            Options o = new Options();
            for (int i = 0; i < args.length; i++) {
                String a = args[i];
                switch (a) {
                    case "-h", "--help" -> o.help = true;
                    case "-q", "--quiet" -> o.quiet = true;
                    case "-o", "--output" -> o.output = Path.of(Args.value(args, ++i, a));
                    case "--width" -> o.width = Args.positive(args, ++i, a);
                    case "--height" -> o.height = Args.positive(args, ++i, a);
                    case "--samples" -> o.samples = Args.positive(args, ++i, a);
                    case "--sampler" -> o.sampler = Args.value(args, ++i, a);
                    case "--adaptive" -> o.adaptive = Args.number(args, ++i, a);
                    case "--threads" -> o.threads = Args.positive(args, ++i, a);
                    default -> {
                        if (a.startsWith("-")) {
                            throw new IllegalArgumentException("unknown option " + a);
                        }
                        if (o.scene != null) {
                            throw new IllegalArgumentException("only one scene file, please (got " + o.scene + " and " + a + ")");
                        }
                        o.scene = Path.of(a);
                    }
                }
            }
            if (o.scene == null && !o.help) {
                throw new IllegalArgumentException("no scene file given");
            }
            return o;
        }

        /** The command-line settings as overrides of scene fields, applied before validation. */
        Map<String, Object> overrides() {
            Map<String, Object> map = new LinkedHashMap<>();
            if (width != null) {
                map.put("image.width", width);
            }
            if (height != null) {
                map.put("image.height", height);
            }
            if (samples != null) {
                map.put("render.samples", samples);
            }
            if (adaptive != null) {
                map.put("render.adaptive", adaptive);
            }
            if (sampler != null) {
                map.put("render.sampler", sampler);
            }
            if (output != null && formatOf(output) != null) {
                map.put("image.format", formatOf(output));
            }
            return map;
        }

    }
}

package studio.bench.accuracy;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Stream;

import studio.server.cli.Args;
import studio.bench.ResolvedScene;
import studio.server.render.ImageFiles;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.MeshFiles;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.format.InvalidSceneException;
import studio.server.scene.format.SceneDto;
import studio.server.scene.reading.LazyValidation;
import studio.server.scene.reading.SceneReader;

/**
 * {@code studio-bench.jar accuracy [--out docs/bench] [--width W] [--height H] [--runs N] [--forks N]
 * [--thresholds T,T,...] [--reference-samples N] [--scenes scenes/bench] [--povray PATH | --no-povray]}: the
 * speed-against-accuracy benchmark of the samplers, and of POV-Ray beside them. Each scene is rendered
 * at its file's own image size, or at {@code --width} and {@code --height} where given. For each scene file
 * it renders a reference with many jittered samples, measures every available sampler (and adaptive
 * sampling, when the engine has it) for time and error, and POV-Ray's fixed grid and adaptive
 * anti-aliasing against POV-Ray's own reference ({@link PovrayAccuracy}; left out when POV-Ray is
 * not installed), repeats the timing (ours and POV-Ray's) in {@code --forks - 1} fresh JVMs
 * ({@link Forks}), and writes
 * {@code speed-accuracy.csv}, each JVM's own times ({@code speed-accuracy-jvms.csv}, with more than
 * one JVM), the charts, the reference images and {@code summary.txt} to the output folder.
 */
public final class BenchCommand {

    /** Exit codes, as the render command's: 0 done, 1 could not read or write a file, 2 bad arguments or an invalid scene. */
    static final int OK = 0, IO_ERROR = 1, INVALID = 2;

    static final int DEFAULT_RUNS = 2, DEFAULT_FORKS = 5, DEFAULT_REFERENCE_SAMPLES = 1024;

    static final String USAGE = "usage: java -jar studio-bench.jar accuracy [--out docs/bench] [--width W --height H "
            + "(default: each scene file's own)] [--runs " + DEFAULT_RUNS + "] [--forks " + DEFAULT_FORKS
            + "] [--thresholds 0.5,0.3,...,0.01] [--reference-samples "
            + DEFAULT_REFERENCE_SAMPLES + "] [--scenes scenes/bench] [--povray /usr/bin/povray | --no-povray]";

    private BenchCommand() {
    }

    public static int run(String[] args, PrintStream out, PrintStream err) {
        long start = System.nanoTime();
        Options options = Args.options(args, Options::parse, USAGE, err);
        if (options == null) {
            return INVALID;
        }
        if (options.help) {
            out.println(USAGE);
            return OK;
        }
        System.setProperty("java.awt.headless", "true");

        Map<String, CompiledScene> scenes = new LinkedHashMap<>();
        Map<String, ResolvedScene> forPovray = new LinkedHashMap<>();
        try (LazyValidation validation = new LazyValidation()) {
            SceneCompiler compiler = SceneCompiler.standalone(validation);
            SceneReader reader = new SceneReader(validation);
            for (Path file : sceneFiles(options.scenes)) {
                try {
                    byte[] json = Files.readAllBytes(file);
                    MeshFiles meshes = MeshFiles.in(file.toAbsolutePath().getParent());
                    CompiledScene compiled = compiler.compile(CompileRequest.of(json).overriding(options.overrides()).readingMeshesFrom(meshes));
                    scenes.put(stem(file), compiled);
                    SceneDto dto = reader.read(json);
                    if (!textured(dto)) { // the POV-Ray writer has no textures: it would render another scene
                        forPovray.put(stem(file), ResolvedScene.of(dto, compiled.settings().width(),
                                compiled.settings().height(), meshes));
                    }
                } catch (InvalidSceneException e) {
                    err.println("error: invalid scene " + file + ": " + e.getMessage());
                    return INVALID;
                }
            }
        } catch (IOException e) {
            err.println("error: cannot read the scenes in " + options.scenes + ": " + e.getMessage());
            return IO_ERROR;
        }
        if (scenes.isEmpty()) {
            err.println("error: no scene files (*.json) in " + options.scenes);
            return INVALID;
        }

        SpeedAccuracyBench bench = new SpeedAccuracyBench(
                SpeedAccuracyBench.Config.defaults(options.runs, options.referenceSamples)
                        .withThresholds(options.thresholds), err);
        PovrayAccuracy povray = null;
        if (options.povray != null && Files.isExecutable(options.povray)) {
            try {
                povray = new PovrayAccuracy(options.povray, Files.createTempDirectory("studio-bench-povray"),
                        Runtime.getRuntime().availableProcessors(), err);
            } catch (IOException e) {
                err.println("error: cannot make a folder for POV-Ray's files: " + e.getMessage());
                return IO_ERROR;
            }
        } else if (options.povray != null) {
            err.println("bench: no POV-Ray at " + options.povray + " (apt-get install povray), so the chart has only ours");
        }
        if (options.timesOnly != null) {
            List<Measurement> times = new ArrayList<>();
            try {
                for (Map.Entry<String, CompiledScene> scene : scenes.entrySet()) {
                    PovrayAccuracy.Scene povrayScene = povray == null || !forPovray.containsKey(scene.getKey()) ? null
                            : povray.prepareTimesOnly(scene.getKey(), forPovray.get(scene.getKey()));
                    times.addAll(bench.timesOnly(scene.getKey(), scene.getValue(), povrayScene));
                }
                BenchCsv.write(options.timesOnly, times);
            } catch (IOException | java.io.UncheckedIOException e) {
                err.println("error: " + e.getMessage());
                return IO_ERROR;
            }
            return OK;
        }
        err.printf(Locale.ROOT, "bench: %d scenes (%s) on %d threads, %d rounds (every setting once a round) in each of "
                        + "%d JVMs, reference %s at %d samples/pixel; adaptive sampling %s%n", scenes.size(), sizes(scenes),
                Runtime.getRuntime().availableProcessors(), options.runs, options.forks,
                SpeedAccuracyBench.REFERENCE_SAMPLER,
                options.referenceSamples, EngineFeatures.hasAdaptive() ? "measured" : "not in this engine, skipped");
        Map<String, List<Measurement>> rowsByScene = new LinkedHashMap<>();
        List<Measurement> all = new ArrayList<>();
        List<List<Measurement>> jvms = List.of();
        try {
            Files.createDirectories(options.out);
            for (Map.Entry<String, CompiledScene> scene : scenes.entrySet()) {
                PovrayAccuracy.Scene povrayScene = povray == null || !forPovray.containsKey(scene.getKey()) ? null
                        : povray.prepare(scene.getKey(), forPovray.get(scene.getKey()));
                SpeedAccuracyBench.SceneResult result = bench.run(scene.getKey(), scene.getValue(), povrayScene);
                rowsByScene.put(scene.getKey(), result.rows());
                all.addAll(result.rows());
                try (OutputStream image = Files.newOutputStream(options.out.resolve("reference-" + scene.getKey() + ".png"))) {
                    ImageFiles.write(result.reference(), "png", 1.0, image);
                }
            }
            if (options.forks > 1) {
                // a fork does less than this JVM did (no references), so this JVM's time bounds it
                Duration bound = Duration.ofNanos(System.nanoTime() - start).multipliedBy(2).plusMinutes(5);
                Path dir = Files.createTempDirectory("studio-bench-forks");
                List<List<Measurement>> forks = new ArrayList<>();
                for (int fork = 2; fork <= options.forks; fork++) {
                    forks.add(Forks.run(options.forkArguments(povray != null), dir, fork, bound, err));
                }
                Files.delete(dir);
                jvms = Forks.withFirstErrors(all, forks);
                Files.writeString(options.out.resolve("speed-accuracy-jvms.csv"), BenchCsv.formatByJvm(jvms));
                List<Measurement> merged = Forks.merge(all, forks);
                all.clear();
                all.addAll(merged);
                rowsByScene.replaceAll((scene, rows) -> merged.stream().filter(m -> m.scene().equals(scene)).toList());
            }
            BenchCsv.write(options.out.resolve("speed-accuracy.csv"), all);
            BenchCharts.write(options.out, rowsByScene);
        } catch (IOException | java.io.UncheckedIOException e) {
            err.println("error: " + e.getMessage());
            return IO_ERROR;
        }

        StringBuilder summary = new StringBuilder();
        summary.append(String.format(Locale.ROOT, "Speed against accuracy, on %d threads; time: the median over %d "
                        + "JVMs of each one's median of %d rounds (POV-Ray's too, started by each JVM); "
                        + "error against %s at %d samples/pixel, RMSE in linear light, PSNR peak 1.0.%n"
                        + "slope: least squares of log RMSE against log samples/pixel (4..256; adaptive: all thresholds, "
                        + "mean samples/pixel).%n"
                        + "ms to target: time to reach jittered's RMSE at 16 samples/pixel, interpolated log-log%s; "
                        + "spp to target: the mean samples/pixel there, interpolated the same way (no clock in it).%n%n",
                Runtime.getRuntime().availableProcessors(), options.forks, options.runs,
                SpeedAccuracyBench.REFERENCE_SAMPLER, options.referenceSamples,
                jvms.size() > 1 ? "; vs jittered: the median over the JVMs of each one's own ratio" : ""));
        for (Map.Entry<String, List<Measurement>> scene : rowsByScene.entrySet()) {
            List<List<Measurement>> sceneJvms = jvms.stream()
                    .map(rows -> rows.stream().filter(m -> m.scene().equals(scene.getKey())).toList()).toList();
            summary.append(BenchSummary.format(scene.getKey() + " at " + size(scenes.get(scene.getKey())), scene.getValue(),
                    sceneJvms)).append('\n');
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        summary.append(String.format(Locale.ROOT, "bench took %.1f s%n", seconds));
        try {
            Files.writeString(options.out.resolve("summary.txt"), summary.toString());
        } catch (IOException e) {
            err.println("error: cannot write to " + options.out + ": " + e.getMessage());
            return IO_ERROR;
        }
        out.print(summary);
        out.println("wrote " + options.out.resolve("speed-accuracy.csv") + ", the charts and summary.txt");
        return OK;
    }

    static List<Path> sceneFiles(Path dir) throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.filter(p -> p.getFileName().toString().endsWith(".json")).sorted().toList();
        }
    }

    /** A scene's image size, as {@code 640x480}. */
    static String size(CompiledScene scene) {
        return scene.settings().width() + "x" + scene.settings().height();
    }

    /** Each scene's name and image size, as {@code edges 640x480, glass 320x240}. */
    static String sizes(Map<String, CompiledScene> scenes) {
        return String.join(", ", scenes.entrySet().stream().map(e -> e.getKey() + " " + size(e.getValue())).toList());
    }

    static String stem(Path file) {
        String name = file.getFileName().toString();
        return name.substring(0, name.length() - ".json".length());
    }

    /** The parsed command line. */
    static final class Options {
        Path out = Path.of("docs/bench");
        Path scenes = Path.of("scenes/bench");
        /** The image size for every scene; null: each scene file's own. */
        Integer width, height;
        int runs = DEFAULT_RUNS, forks = DEFAULT_FORKS, referenceSamples = DEFAULT_REFERENCE_SAMPLES;
        /** Set in a fork: time our settings only and write the rows here. */
        Path timesOnly;
        /** POV-Ray's executable; null: leave POV-Ray out. */
        Path povray = Path.of("/usr/bin/povray");
        /** The adaptive thresholds to measure; null: the defaults (0.5 to 0.01). */
        List<Double> thresholds;
        boolean help;

        static Options parse(String[] args) {
            Options o = new Options();
            for (int i = 0; i < args.length; i++) {
                String a = args[i];
                switch (a) {
                    case "-h", "--help" -> o.help = true;
                    case "--out" -> o.out = Path.of(Args.value(args, ++i, a));
                    case "--scenes" -> o.scenes = Path.of(Args.value(args, ++i, a));
                    case "--width" -> o.width = Args.positive(args, ++i, a);
                    case "--height" -> o.height = Args.positive(args, ++i, a);
                    case "--runs" -> o.runs = Args.positive(args, ++i, a);
                    case "--forks" -> o.forks = Args.positive(args, ++i, a);
                    case "--times-only" -> o.timesOnly = Path.of(Args.value(args, ++i, a));
                    case "--reference-samples" -> o.referenceSamples = Args.positive(args, ++i, a);
                    case "--povray" -> o.povray = Path.of(Args.value(args, ++i, a));
                    case "--no-povray" -> o.povray = null;
                    case "--thresholds" -> o.thresholds = thresholds(Args.value(args, ++i, a));
                    default -> throw new IllegalArgumentException("unknown argument " + a);
                }
            }
            return o;
        }

        /** A fork's arguments: the same scenes, sizes and rounds, and POV-Ray if this JVM ran it. */
        List<String> forkArguments(boolean withPovray) {
            List<String> arguments = new ArrayList<>(List.of("--scenes", scenes.toString()));
            if (width != null) {
                arguments.addAll(List.of("--width", width.toString()));
            }
            if (height != null) {
                arguments.addAll(List.of("--height", height.toString()));
            }
            arguments.addAll(List.of("--runs", Integer.toString(runs)));
            if (thresholds != null) {
                arguments.addAll(List.of("--thresholds", String.join(",", thresholds.stream().map(String::valueOf).toList())));
            }
            arguments.addAll(withPovray ? List.of("--povray", povray.toString()) : List.of("--no-povray"));
            return arguments;
        }

        /** A comma-separated list of thresholds, each finite and above 0. */
        static List<Double> thresholds(String list) {
            List<Double> values = new ArrayList<>();
            for (String part : list.split(",")) {
                double value;
                try {
                    value = Double.parseDouble(part.trim());
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException("--thresholds: '" + part + "' is not a number");
                }
                if (!(value > 0) || Double.isInfinite(value)) {
                    throw new IllegalArgumentException("--thresholds: " + part + " must be above 0");
                }
                values.add(value);
            }
            return List.copyOf(values);
        }

        /** The image size given on the command line, as overrides of the scene files' fields, applied before validation. */
        Map<String, Object> overrides() {
            Map<String, Object> overrides = new LinkedHashMap<>();
            if (width != null) {
                overrides.put("image.width", width);
            }
            if (height != null) {
                overrides.put("image.height", height);
            }
            return overrides;
        }

    }

    /** Whether any of the scene's materials has a texture. */
    private static boolean textured(SceneDto dto) {
        return dto.objects().stream().anyMatch(o -> o.material() != null && o.material().texture() != null);
    }
}

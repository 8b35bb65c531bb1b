package studio.bench.accuracy;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import studio.bench.PovrayScene;
import studio.bench.ProcessRun;
import studio.bench.ResolvedScene;

/**
 * POV-Ray on the speed-against-accuracy chart: the same scene (written by {@link PovrayScene}, as
 * the peer benchmark writes it) rendered by POV-Ray 3.7 with its fixed grid ({@code +AM1}, every
 * pixel supersampled with k x k rays) and its adaptive anti-aliasing ({@code +AM2}, recursive
 * subdivision where neighbouring samples differ by more than a threshold), each timed by POV-Ray's
 * own "Trace Time" and the CPU seconds it reports beside it (the render, without start-up and
 * parsing, as ours is timed warm in one JVM) and measured against POV-Ray's own reference: the scene at {@value #REFERENCE_SCALE} times the
 * size with an 8 x 8 grid a pixel, averaged back down, so 1,024 samples a pixel as ours has.
 * Each renderer's error is against its own converged image, so the curves compare how fast each
 * gets to its own answer, not whose answer is right. POV-Ray writes 16-bit sRGB PNGs, clamped to
 * [0, 1]; our films are not clamped, so bright highlights count against ours only.
 *
 * <p>A scene with sphere or area lights is measured instead along POV-Ray's {@code area_light}
 * settings: grids of {@link #AREA_GRID} sub-lights a side, each plain, {@code adaptive}, {@code jitter}ed
 * and both ({@code povray-area}, {@code povray-area-adaptive}, {@code povray-area-jitter},
 * {@code povray-area-adaptive-jitter}), every one with the adaptive anti-aliasing {@link #AREA_AA};
 * its reference has a {@value #REFERENCE_AREA_GRID} x {@value #REFERENCE_AREA_GRID} jittered grid
 * under 64 camera rays a pixel ({@link #REFERENCE_SOFT_GRID}).
 */
final class PovrayAccuracy {

    /** The grid sizes k of the fixed-grid settings (k x k samples; 1 is one ray through the centre). */
    static final int[] GRID = {1, 2, 4, 8};
    /** The thresholds of the adaptive settings ({@code +A}), at recursion depth {@value #ADAPTIVE_DEPTH}. */
    static final double[] THRESHOLDS = {0.3, 0.1, 0.05, 0.02, 0.01};
    /** {@code +R} for the adaptive method: up to (2^depth + 1)^2 samples a pixel. */
    static final int ADAPTIVE_DEPTH = 3;
    static final int REFERENCE_SCALE = 4, REFERENCE_GRID = 8;

    static final String GRID_METHOD = "povray-grid", ADAPTIVE_METHOD = "povray-adaptive";
    /** The sub-lights a side of the {@code area_light} settings, and of the reference's. */
    static final int[] AREA_GRID = {2, 4, 8, 16};
    static final int REFERENCE_AREA_GRID = 8;
    /**
     * The reference's anti-aliasing grid a pixel of its 4 x larger image on a soft-lit scene: 2 x 2,
     * 64 camera rays a pixel, each with the 8 x 8 jittered sub-lights (as many shadow rays as 1,024
     * camera rays with 2 x 2 sub-lights, which left a bias: on soft-ball at 160x120 POV-Ray's error
     * against it grew with the grid, 0.0046 at 2 x 2 jittered to 0.0126 at 16 x 16).
     */
    static final int REFERENCE_SOFT_GRID = 2;
    /**
     * The anti-aliasing of every {@code area_light} setting: adaptive, threshold 0.02, depth 3 (at 0.1
     * the edges' error left a floor under the curves on {@code soft-ball} at 80x60, 2-4e-3, higher at
     * larger grids, whose smoother shadows set off fewer anti-aliasing samples).
     */
    static final List<String> AREA_AA = List.of("+A0.02", "+AM2", "+R3");

    static final Pattern TRACE_TIME = Pattern.compile("Trace Time:.*\\(([0-9.]+) seconds\\)");
    /**
     * The line under the trace time, "using 2 thread(s) with 0.017 CPU-seconds total" (the parse
     * and bounding times above it have lines of their own of the same form).
     */
    static final Pattern CPU_TIME = Pattern.compile("Trace Time:[^\\n]*\\n\\s*using [0-9]+ thread\\(s\\) with ([0-9.]+) CPU-seconds total");
    /** POV-Ray's counts of pixel rays (an extra row and column under anti-aliasing) and anti-aliasing samples. */
    private static final Pattern PIXELS = Pattern.compile("Pixels:\\s*([0-9]+)"), SAMPLES = Pattern.compile("Samples:\\s*([0-9]+)");

    /** One POV-Ray setting; {@code area} how it samples lights with a size (null: the scene has none). */
    record Setting(String method, int samples, double threshold, List<String> options, PovrayScene.AreaSampling area) {
    }

    private final Path povray;
    private final Path work;
    private final int threads;
    private final PrintStream log;

    PovrayAccuracy(Path povray, Path work, int threads, PrintStream log) {
        this.povray = povray;
        this.work = work;
        this.threads = threads;
        this.log = log;
    }

    /** The settings measured: the fixed grids, then the adaptive thresholds. */
    static List<Setting> settings() {
        List<Setting> settings = new ArrayList<>();
        for (int k : GRID) {
            settings.add(new Setting(GRID_METHOD, k * k, Double.NaN,
                    k == 1 ? List.of("-A") : List.of("+A0.0", "+AM1", "+R" + k), null));
        }
        for (double t : THRESHOLDS) {
            settings.add(new Setting(ADAPTIVE_METHOD, (1 << ADAPTIVE_DEPTH) * (1 << ADAPTIVE_DEPTH), t,
                    List.of(String.format(Locale.ROOT, "+A%.3f", t), "+AM2", "+R" + ADAPTIVE_DEPTH), null));
        }
        return settings;
    }

    /** The settings measured for a scene with sphere or area lights: each area_light variant at each grid. */
    static List<Setting> areaSettings() {
        List<Setting> settings = new ArrayList<>();
        for (boolean adaptive : new boolean[] {false, true}) {
            for (boolean jitter : new boolean[] {false, true}) {
                String method = "povray-area" + (adaptive ? "-adaptive" : "") + (jitter ? "-jitter" : "");
                for (int k : AREA_GRID) {
                    settings.add(new Setting(method, k * k, Double.NaN, AREA_AA,
                            new PovrayScene.AreaSampling(k, adaptive, jitter)));
                }
            }
        }
        return settings;
    }

    private static boolean soft(ResolvedScene scene) {
        return scene.lights().stream().anyMatch(ResolvedScene.Light::soft);
    }

    /** A scene written for POV-Ray, with its reference rendered; {@link #round} times its settings. */
    Scene prepare(String name, ResolvedScene scene) throws IOException {
        Path dir = Files.createDirectories(work.resolve(name));
        Path pov = Files.writeString(dir.resolve("reference.pov"), PovrayScene.of(scene, name,
                new PovrayScene.AreaSampling(REFERENCE_AREA_GRID, false, true)));
        Path out = dir.resolve("reference.png");
        long start = System.nanoTime();
        int grid = soft(scene) ? REFERENCE_SOFT_GRID : REFERENCE_GRID;
        ProcessRun.time(command(pov, out, scene.width() * REFERENCE_SCALE, scene.height() * REFERENCE_SCALE,
                List.of("+A0.0", "+AM1", "+R" + grid)), out, dir.resolve("reference.log"));
        log.printf(Locale.ROOT, "%s: POV-Ray reference, %d samples/pixel, %.0f ms%n", name,
                REFERENCE_SCALE * REFERENCE_SCALE * grid * grid, (System.nanoTime() - start) / 1e6);
        return new Scene(name, dir, scene, PovrayImage.linear(out, REFERENCE_SCALE));
    }

    /**
     * As {@link #prepare}, without the reference, for another JVM's share of the rounds
     * ({@code --forks}): its rows have times and no error.
     */
    Scene prepareTimesOnly(String name, ResolvedScene scene) throws IOException {
        return new Scene(name, Files.createDirectories(work.resolve(name)), scene, null);
    }

    /** One scene's POV-Ray settings and what they measured so far. */
    final class Scene {
        private final String name;
        private final Path dir;
        /** Per setting, the scene in POV-Ray's language (one file for all, unless lights with a size are sampled differently). */
        private final List<Path> povs = new ArrayList<>();
        private final int width, height;
        /** POV-Ray's converged image in linear light; null when only times are measured. */
        private final double[] reference;
        private final List<Setting> settings;
        private final List<List<Double>> millis = new ArrayList<>(), cpuMillis = new ArrayList<>();
        private final double[] rmse, samplesPerPixel;

        Scene(String name, Path dir, ResolvedScene scene, double[] reference) throws IOException {
            this.name = name;
            this.dir = dir;
            this.width = scene.width();
            this.height = scene.height();
            this.reference = reference;
            this.settings = soft(scene) ? areaSettings() : settings();
            Path shared = Files.writeString(dir.resolve("scene.pov"), PovrayScene.of(scene, name));
            for (int i = 0; i < settings.size(); i++) {
                PovrayScene.AreaSampling area = settings.get(i).area();
                povs.add(area == null ? shared
                        : Files.writeString(dir.resolve("setting-" + i + ".pov"), PovrayScene.of(scene, name, area)));
            }
            this.rmse = new double[settings.size()];
            this.samplesPerPixel = new double[settings.size()];
            settings.forEach(s -> {
                millis.add(new ArrayList<>());
                cpuMillis.add(new ArrayList<>());
            });
        }

        /** Renders every setting once; the first round also measures the errors (NaN without a reference). */
        void round() throws IOException {
            for (int i = 0; i < settings.size(); i++) {
                Setting s = settings.get(i);
                Path out = dir.resolve("setting-" + i + ".png"), logFile = dir.resolve("setting-" + i + ".log");
                ProcessRun.time(command(povs.get(i), out, width, height, s.options()), out, logFile);
                String stats = Files.readString(logFile);
                millis.get(i).add(1000 * number(TRACE_TIME, stats, logFile));
                cpuMillis.get(i).add(1000 * number(CPU_TIME, stats, logFile));
                if (millis.get(i).size() == 1) {
                    rmse[i] = reference == null ? Double.NaN : ImageError.rmse(PovrayImage.linear(out, 1), reference);
                    // every camera ray: the pixels' own and the anti-aliasing samples, per pixel of the image
                    samplesPerPixel[i] = (number(PIXELS, stats, logFile) + number(SAMPLES, stats, logFile))
                            / ((double) width * height);
                }
            }
        }

        /** The rows, with the median of each setting's times (wall and CPU). */
        List<Measurement> rows() {
            List<Measurement> rows = new ArrayList<>();
            for (int i = 0; i < settings.size(); i++) {
                Setting s = settings.get(i);
                double[] times = millis.get(i).stream().mapToDouble(Double::doubleValue).toArray();
                double[] cpu = cpuMillis.get(i).stream().mapToDouble(Double::doubleValue).toArray();
                Measurement m = new Measurement(name, s.method(), s.samples(), samplesPerPixel[i],
                        SpeedAccuracyBench.median(times), SpeedAccuracyBench.median(cpu), rmse[i],
                        Double.isNaN(rmse[i]) ? Double.NaN : ImageError.psnr(rmse[i]), s.threshold());
                log.printf(Locale.ROOT, "%s: %-27s %4d spp (mean %6.1f) %9.1f ms  rmse %.5f  psnr %5.2f dB%n", name,
                        Double.isNaN(s.threshold()) ? s.method() : s.method() + " " + s.threshold(), s.samples(),
                        samplesPerPixel[i], m.medianMillis(), rmse[i], m.psnr());
                rows.add(m);
            }
            return rows;
        }
    }

    private List<String> command(Path pov, Path out, int w, int h, List<String> options) {
        List<String> command = new ArrayList<>(List.of(povray.toString(), "+I" + pov, "+O" + out, "+W" + w, "+H" + h,
                "+WT" + threads, "-D", "-V", "+FN16", "-P"));
        command.addAll(options);
        return command;
    }

    static double number(Pattern pattern, String stats, Path file) throws IOException {
        Matcher m = pattern.matcher(stats);
        if (!m.find()) {
            throw new IOException("no " + pattern.pattern() + " in POV-Ray's statistics, " + file);
        }
        return Double.parseDouble(m.group(1));
    }
}

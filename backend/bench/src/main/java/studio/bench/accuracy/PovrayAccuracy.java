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

    static final Pattern TRACE_TIME = Pattern.compile("Trace Time:.*\\(([0-9.]+) seconds\\)");
    /**
     * The line under the trace time, "using 2 thread(s) with 0.017 CPU-seconds total" (the parse
     * and bounding times above it have lines of their own of the same form).
     */
    static final Pattern CPU_TIME = Pattern.compile("Trace Time:[^\\n]*\\n\\s*using [0-9]+ thread\\(s\\) with ([0-9.]+) CPU-seconds total");
    /** POV-Ray's counts of pixel rays (an extra row and column under anti-aliasing) and anti-aliasing samples. */
    private static final Pattern PIXELS = Pattern.compile("Pixels:\\s*([0-9]+)"), SAMPLES = Pattern.compile("Samples:\\s*([0-9]+)");

    /** One POV-Ray setting. */
    record Setting(String method, int samples, double threshold, List<String> options) {
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
                    k == 1 ? List.of("-A") : List.of("+A0.0", "+AM1", "+R" + k)));
        }
        for (double t : THRESHOLDS) {
            settings.add(new Setting(ADAPTIVE_METHOD, (1 << ADAPTIVE_DEPTH) * (1 << ADAPTIVE_DEPTH), t,
                    List.of(String.format(Locale.ROOT, "+A%.3f", t), "+AM2", "+R" + ADAPTIVE_DEPTH)));
        }
        return settings;
    }

    /** A scene written for POV-Ray, with its reference rendered; {@link #round} times its settings. */
    Scene prepare(String name, ResolvedScene scene) throws IOException {
        Path pov = writeScene(name, scene), dir = pov.getParent();
        Path out = dir.resolve("reference.png");
        long start = System.nanoTime();
        ProcessRun.time(command(pov, out, scene.width() * REFERENCE_SCALE, scene.height() * REFERENCE_SCALE,
                List.of("+A0.0", "+AM1", "+R" + REFERENCE_GRID)), out, dir.resolve("reference.log"));
        log.printf(Locale.ROOT, "%s: POV-Ray reference, %d samples/pixel, %.0f ms%n", name,
                REFERENCE_SCALE * REFERENCE_SCALE * REFERENCE_GRID * REFERENCE_GRID, (System.nanoTime() - start) / 1e6);
        return new Scene(name, dir, pov, scene.width(), scene.height(), PovrayImage.linear(out, REFERENCE_SCALE), settings());
    }

    /**
     * As {@link #prepare}, without the reference, for another JVM's share of the rounds
     * ({@code --forks}): its rows have times and no error.
     */
    Scene prepareTimesOnly(String name, ResolvedScene scene) throws IOException {
        Path pov = writeScene(name, scene);
        return new Scene(name, pov.getParent(), pov, scene.width(), scene.height(), null, settings());
    }

    /** The scene in POV-Ray's language, written to {@code scene.pov} in a folder of its own. */
    private Path writeScene(String name, ResolvedScene scene) throws IOException {
        Path dir = Files.createDirectories(work.resolve(name));
        return Files.writeString(dir.resolve("scene.pov"), PovrayScene.of(scene, name));
    }

    /** One scene's POV-Ray settings and what they measured so far. */
    final class Scene {
        private final String name;
        private final Path dir, pov;
        private final int width, height;
        /** POV-Ray's converged image in linear light; null when only times are measured. */
        private final double[] reference;
        private final List<Setting> settings;
        private final List<List<Double>> millis = new ArrayList<>(), cpuMillis = new ArrayList<>();
        private final double[] rmse, samplesPerPixel;

        Scene(String name, Path dir, Path pov, int width, int height, double[] reference, List<Setting> settings) {
            this.name = name;
            this.dir = dir;
            this.pov = pov;
            this.width = width;
            this.height = height;
            this.reference = reference;
            this.settings = settings;
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
                ProcessRun.time(command(pov, out, width, height, s.options()), out, logFile);
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
                log.printf(Locale.ROOT, "%s: %-20s %4d spp (mean %6.1f) %9.1f ms  rmse %.5f  psnr %5.2f dB%n", name,
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

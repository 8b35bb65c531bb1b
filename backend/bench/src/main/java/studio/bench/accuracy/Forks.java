package studio.bench.accuracy;

import java.io.IOException;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import studio.bench.ProcessRun;

/**
 * The benchmark's rounds repeated in fresh JVMs ({@code --forks}), as JMH forks its benchmarks.
 * Renders of 20-500 ms in one JVM measure that JVM's compiled code as well as the renderer: the JIT
 * inlines and lays out the hot loops a little differently each time, and the same setting took up to
 * a third longer in one JVM than in the next, always the same way in both (soft-shadows' ratio to
 * jittered came out 0.24 and 0.33 in two runs). Each fork warms up and times every setting in
 * rounds as the first JVM did, POV-Ray's too when the first JVM ran it, without a reference, and
 * writes its medians to a CSV file; a row's time is then the median over the JVMs of their medians.
 * POV-Ray's renders are processes of their own, so no JVM's compiled code touches them; they are
 * timed in every JVM's rounds all the same, so that both renderers are sampled over the whole run
 * (on this machine a slow or fast spell lasts minutes, and POV-Ray's renders of 20-40 ms timed in
 * the first JVM's rounds alone moved the chart's worst ratio to POV-Ray from 0.52 to 0.90 between
 * two days).
 */
final class Forks {

    private Forks() {
    }

    /**
     * Runs this benchmark's timing in a new JVM, with this JVM's Java, class path and -X options, and
     * reads back its rows (its files in {@code dir} are deleted then; kept when it fails); waits at
     * most {@code bound}.
     *
     * @param arguments the accuracy command's arguments for the fork, without {@code --times-only}
     * @throws IOException if it could not start, failed, ran over its bound or wrote no rows (the
     *                     message has the end of its log)
     */
    static List<Measurement> run(List<String> arguments, Path dir, int index, Duration bound, PrintStream log)
            throws IOException {
        Path times = dir.resolve("times-" + index + ".csv"), output = dir.resolve("fork-" + index + ".log");
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        for (String option : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
            if (option.startsWith("-X")) {
                command.add(option);
            }
        }
        command.addAll(List.of("-cp", System.getProperty("java.class.path"), "studio.bench.BenchMain", "accuracy",
                "--times-only", times.toString()));
        command.addAll(arguments);
        log.printf(Locale.ROOT, "bench: JVM %d times the same settings (--times-only %s, log %s)%n", index, times, output);
        Process process = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(output.toFile()).start();
        try {
            if (!process.waitFor(bound.toMillis(), TimeUnit.MILLISECONDS)) {
                process.destroyForcibly();
                throw new IOException("JVM " + index + " ran over " + bound.toMinutes() + " minutes\n" + ProcessRun.tail(output));
            }
        } catch (InterruptedException e) {
            process.destroyForcibly();
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
        if (process.exitValue() != 0 || !Files.isRegularFile(times)) {
            throw new IOException("JVM " + index + " exited " + process.exitValue() + "\n" + ProcessRun.tail(output));
        }
        List<Measurement> rows = BenchCsv.read(times);
        Files.delete(times);
        Files.delete(output);
        return rows;
    }

    /**
     * The first JVM's rows with each time (wall and CPU) replaced by the median of that row's time over
     * every JVM that measured it; the errors and samples stay, and so does a row no fork measured
     * (POV-Ray's, when the forks ran without it).
     */
    static List<Measurement> merge(List<Measurement> first, List<List<Measurement>> forks) {
        Map<String, List<Measurement>> byKey = new HashMap<>();
        for (List<Measurement> fork : forks) {
            for (Measurement m : fork) {
                byKey.computeIfAbsent(key(m), k -> new ArrayList<>()).add(m);
            }
        }
        List<Measurement> merged = new ArrayList<>();
        for (Measurement m : first) {
            List<Measurement> same = byKey.getOrDefault(key(m), List.of());
            double[] wall = new double[same.size() + 1], cpu = new double[same.size() + 1];
            wall[0] = m.medianMillis();
            cpu[0] = m.medianCpuMillis();
            for (int i = 0; i < same.size(); i++) {
                wall[i + 1] = same.get(i).medianMillis();
                cpu[i + 1] = same.get(i).medianCpuMillis();
            }
            merged.add(new Measurement(m.scene(), m.method(), m.samples(), m.meanSamplesPerPixel(),
                    SpeedAccuracyBench.median(wall), SpeedAccuracyBench.median(cpu), m.rmse(), m.psnr(), m.threshold()));
        }
        return merged;
    }

    /**
     * The first JVM's rows, then each fork's, every row with the error of the first JVM's row of the
     * same setting (a fork renders no reference); a setting the first JVM did not measure is left out.
     */
    static List<List<Measurement>> withFirstErrors(List<Measurement> first, List<List<Measurement>> forks) {
        Map<String, Measurement> firstByKey = new HashMap<>();
        first.forEach(m -> firstByKey.put(key(m), m));
        List<List<Measurement>> jvms = new ArrayList<>();
        jvms.add(List.copyOf(first));
        for (List<Measurement> fork : forks) {
            List<Measurement> rows = new ArrayList<>();
            for (Measurement m : fork) {
                Measurement own = firstByKey.get(key(m));
                if (own != null) {
                    rows.add(new Measurement(m.scene(), m.method(), m.samples(), own.meanSamplesPerPixel(),
                            m.medianMillis(), m.medianCpuMillis(), own.rmse(), own.psnr(), m.threshold()));
                }
            }
            jvms.add(rows);
        }
        return jvms;
    }

    private static String key(Measurement m) {
        return m.scene() + "," + m.method() + "," + m.samples() + "," + m.threshold();
    }
}

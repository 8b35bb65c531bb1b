package studio.bench.accuracy;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.OptionalDouble;
import java.util.Set;
import java.util.function.ToDoubleFunction;

/**
 * The summary of one scene: for each method, how fast its error falls with samples (the
 * least-squares slope of log RMSE against log samples per pixel, over 4..256 for fixed counts and
 * over every threshold for adaptive sampling, against the mean samples per pixel), and how long it
 * takes to reach the error that jittered sampling reaches at 16 samples, also as a ratio to
 * jittered's own time, by the wall clock and by the renders' CPU time (the second is what a render
 * cost whatever else the machine did meanwhile: on a shared machine it is the figure that repeats).
 */
final class BenchSummary {

    static final String TARGET_SAMPLER = "jittered";
    static final int TARGET_SAMPLES = 16;
    static final int SLOPE_FROM = 4, SLOPE_TO = 256;

    /** The error to reach: jittered's RMSE at 16 samples per pixel, and its wall and CPU times. */
    record Target(double rmse, double millis, double cpuMillis) {
    }

    /**
     * One method's line.
     *
     * @param millis     time to reach the target; NaN if it never does
     * @param upperBound true if even the method's cheapest setting is below the target (millis is that setting's time)
     * @param ratio      millis over jittered's time to reach the target
     * @param cpuRatio   the same ratio by CPU time; NaN where CPU time was not measured
     * @param samples    mean samples a pixel to reach the target, interpolated as the time is; NaN if it never
     *                   does. It depends on no clock: a change to sampling shows in it without the machine's noise
     */
    record Line(String method, double slope, double millis, boolean upperBound, double ratio, double cpuRatio,
                double samples) {
    }

    private BenchSummary() {
    }

    /** Jittered at 16 samples, or null if it was not measured. */
    static Target target(List<Measurement> rows) {
        return rows.stream()
                .filter(m -> m.method().equals(TARGET_SAMPLER) && m.samples() == TARGET_SAMPLES && Double.isNaN(m.threshold()))
                .findFirst().map(m -> new Target(m.rmse(), m.medianMillis(), m.medianCpuMillis())).orElse(null);
    }

    /** A method's measurements in order of increasing mean samples per pixel. */
    static List<Measurement> ordered(List<Measurement> own) {
        return own.stream().sorted(Comparator.comparingDouble(Measurement::meanSamplesPerPixel)).toList();
    }

    static OptionalDouble timeToReach(List<Measurement> own, double targetRmse) {
        return timeToReach(own, targetRmse, Measurement::medianMillis);
    }

    /** As {@link #timeToReach(List, double)} by the time {@code time} gives each measurement. */
    static OptionalDouble timeToReach(List<Measurement> own, double targetRmse, ToDoubleFunction<Measurement> time) {
        List<Measurement> sorted = ordered(own);
        return LogLog.timeToReach(sorted.stream().mapToDouble(time).toArray(),
                sorted.stream().mapToDouble(Measurement::rmse).toArray(), targetRmse);
    }

    static double slope(List<Measurement> own) {
        List<Measurement> fitted = ordered(own).stream()
                .filter(m -> !Double.isNaN(m.threshold()) || (m.samples() >= SLOPE_FROM && m.samples() <= SLOPE_TO))
                .toList();
        return LogLog.slope(fitted.stream().mapToDouble(Measurement::meanSamplesPerPixel).toArray(),
                fitted.stream().mapToDouble(Measurement::rmse).toArray());
    }

    /**
     * One line per method of one scene's rows, in the order the methods first appear. Each ratio to
     * jittered is that of the rows' own times, or, where the scene was timed in two JVMs or more
     * ({@code jvms}: each one's rows of the scene, with errors; empty for one JVM), the median over
     * the JVMs of each one's own ratio, both times from the same JVM: a slower JVM, or a slow spell
     * of the machine over one JVM's run, then moves both times of a ratio alike.
     */
    static List<Line> lines(List<Measurement> rows, List<List<Measurement>> jvms) {
        List<Line> lines = ratiosOfMedians(rows);
        if (jvms.size() < 2) {
            return lines;
        }
        List<Map<String, Line>> byJvm = new ArrayList<>();
        for (List<Measurement> jvm : jvms) {
            Map<String, Line> own = new HashMap<>();
            ratiosOfMedians(jvm).forEach(line -> own.put(line.method(), line));
            byJvm.add(own);
        }
        List<Line> paired = new ArrayList<>();
        for (Line line : lines) {
            double[] ratios = new double[jvms.size()], cpuRatios = new double[jvms.size()];
            for (int j = 0; j < jvms.size(); j++) {
                Line own = byJvm.get(j).get(line.method());
                ratios[j] = own == null ? Double.NaN : own.ratio();
                cpuRatios[j] = own == null ? Double.NaN : own.cpuRatio();
            }
            paired.add(new Line(line.method(), line.slope(), line.millis(), line.upperBound(),
                    medianOfMeasured(ratios), medianOfMeasured(cpuRatios), line.samples()));
        }
        return paired;
    }

    /** The median of the values that are not NaN (POV-Ray is timed in the first JVM only); NaN if none is. */
    private static double medianOfMeasured(double[] values) {
        double[] measured = Arrays.stream(values).filter(v -> !Double.isNaN(v)).toArray();
        return measured.length == 0 ? Double.NaN : SpeedAccuracyBench.median(measured);
    }

    /** The lines with each ratio to jittered taken between the rows' own times. */
    private static List<Line> ratiosOfMedians(List<Measurement> rows) {
        Target target = target(rows);
        Set<String> methods = new LinkedHashSet<>();
        rows.forEach(m -> methods.add(m.method()));
        double jitteredMillis = Double.NaN, jitteredCpuMillis = Double.NaN;
        if (target != null) {
            List<Measurement> jittered = rows.stream().filter(m -> m.method().equals(TARGET_SAMPLER)).toList();
            jitteredMillis = timeToReach(jittered, target.rmse()).orElse(target.millis());
            jitteredCpuMillis = timeToReach(jittered, target.rmse(), Measurement::medianCpuMillis)
                    .orElse(target.cpuMillis());
        }
        List<Line> lines = new ArrayList<>();
        for (String method : methods) {
            List<Measurement> own = rows.stream().filter(m -> m.method().equals(method)).toList();
            double millis = Double.NaN, cpuMillis = Double.NaN, samples = Double.NaN;
            boolean upper = false;
            if (target != null) {
                millis = timeToReach(own, target.rmse()).orElse(Double.NaN);
                cpuMillis = timeToReach(own, target.rmse(), Measurement::medianCpuMillis).orElse(Double.NaN);
                samples = timeToReach(own, target.rmse(), Measurement::meanSamplesPerPixel).orElse(Double.NaN);
                upper = !Double.isNaN(millis) && ordered(own).get(0).rmse() <= target.rmse()
                        && !method.equals(TARGET_SAMPLER);
            }
            lines.add(new Line(method, slope(own), millis, upper, millis / jitteredMillis, cpuMillis / jitteredCpuMillis,
                    samples));
        }
        return lines;
    }

    /** The printed table of one scene, its ratios to jittered as {@link #lines} takes them. */
    static String format(String scene, List<Measurement> rows, List<List<Measurement>> jvms) {
        StringBuilder s = new StringBuilder();
        Target target = target(rows);
        if (target == null) {
            s.append(scene).append(": no jittered measurement at ").append(TARGET_SAMPLES).append(" samples, no target\n");
        } else {
            s.append(String.format(Locale.ROOT, "%s: target RMSE %.5f (jittered at %d samples/pixel, %.1f ms)%n",
                    scene, target.rmse(), TARGET_SAMPLES, target.millis()));
        }
        s.append(String.format(Locale.ROOT, "  %-22s %9s %16s %12s %12s %14s%n", "method", "slope", "ms to target", "vs jittered",
                "by CPU time", "spp to target"));
        for (Line line : lines(rows, jvms)) {
            String bound = line.upperBound() ? "<= " : "";
            String millis = Double.isNaN(line.millis()) ? "not reached" : bound + String.format(Locale.ROOT, "%.1f", line.millis());
            String ratio = Double.isNaN(line.ratio()) ? "-" : bound + String.format(Locale.ROOT, "%.2f", line.ratio());
            String cpuRatio = Double.isNaN(line.cpuRatio()) ? "-" : bound + String.format(Locale.ROOT, "%.2f", line.cpuRatio());
            String slope = Double.isNaN(line.slope()) ? "-" : String.format(Locale.ROOT, "%.2f", line.slope());
            String samples = Double.isNaN(line.samples()) ? "-" : bound + String.format(Locale.ROOT, "%.2f", line.samples());
            s.append(String.format(Locale.ROOT, "  %-22s %9s %16s %12s %12s %14s%n", line.method(), slope, millis, ratio, cpuRatio,
                    samples));
        }
        String povray = againstPovray(rows);
        if (!povray.isEmpty()) {
            s.append(povray);
        }
        return s.toString();
    }

    /** Our default method: what a scene without render settings gets. */
    static final String DEFAULT_METHOD = "adaptive-sobol";
    /** The same at the default threshold, with the most samples a pixel may take varied ({@link Method#adaptiveBySamples}). */
    static final String DEFAULT_BY_SAMPLES = Method.adaptiveBySamples("sobol", Double.NaN).name();

    /**
     * Our default method against each POV-Ray setting: the time our default takes to reach that
     * setting's error (interpolated log-log) over POV-Ray's time for it, so below 1 means our curve
     * lies below POV-Ray's there; by the wall and, where both were measured, by CPU time (POV-Ray's
     * own CPU seconds against our render threads'). The default has two knobs, the threshold and
     * the most samples a pixel may take, so its curve is the lower of the two measured along them
     * (the threshold at 256 samples, and the default threshold at 1 to 64 samples), as POV-Ray's
     * best is the lower of its grid and its adaptive method. "&lt;=" where the cheaper curve's
     * cheapest setting is already more accurate, so its time bounds ours from above (the worst
     * ratio counts that bound); a setting whose error neither reaches is listed as such. Empty when
     * POV-Ray was not measured.
     */
    static String againstPovray(List<Measurement> rows) {
        List<List<Measurement>> curves = new ArrayList<>();
        for (String method : List.of(DEFAULT_METHOD, DEFAULT_BY_SAMPLES)) {
            List<Measurement> own = rows.stream().filter(m -> m.method().equals(method)).toList();
            if (!own.isEmpty()) {
                curves.add(own);
            }
        }
        List<Measurement> povray = rows.stream().filter(m -> m.method().startsWith("povray")).toList();
        if (curves.isEmpty() || povray.isEmpty()) {
            return "";
        }
        StringBuilder s = new StringBuilder(String.format(Locale.ROOT,
                "  %s against POV-Ray, at each POV-Ray setting's error: our time / POV-Ray's time (by CPU time)%n",
                curves.size() > 1 ? DEFAULT_METHOD + " (by threshold and by samples)" : DEFAULT_METHOD));
        double worst = 0, worstCpu = 0;
        for (Measurement p : povray) {
            String setting = Double.isNaN(p.threshold()) ? p.samples() + " spp" : "threshold " + p.threshold();
            Reach wall = reach(curves, p.rmse(), Measurement::medianMillis);
            Reach cpu = reach(curves, p.rmse(), Measurement::medianCpuMillis);
            if (Double.isNaN(wall.millis())) {
                s.append(String.format(Locale.ROOT, "    %-16s %-15s rmse %.5f %9.1f ms  below our default's range%n",
                        p.method(), setting, p.rmse(), p.medianMillis()));
                continue;
            }
            double ratio = wall.millis() / p.medianMillis();
            double cpuRatio = cpu.millis() / p.medianCpuMillis();
            worst = Math.max(worst, ratio);
            if (Double.isFinite(cpuRatio)) {
                worstCpu = Math.max(worstCpu, cpuRatio);
            }
            s.append(String.format(Locale.ROOT, "    %-16s %-15s rmse %.5f %9.1f ms  %s%s%n", p.method(), setting, p.rmse(),
                    p.medianMillis(), (wall.bound() ? "<= " : "") + String.format(Locale.ROOT, "%.2f", ratio),
                    Double.isFinite(cpuRatio)
                            ? String.format(Locale.ROOT, " (%s%.2f)", cpu.bound() ? "<= " : "", cpuRatio) : ""));
        }
        s.append(String.format(Locale.ROOT, "    worst ratio %.2f%s%n", worst,
                worstCpu > 0 ? String.format(Locale.ROOT, " (by CPU time %.2f)", worstCpu) : ""));
        return s.toString();
    }

    /** Our time to an error along the cheaper of the curves, and whether it is only an upper bound. */
    private record Reach(double millis, boolean bound) {
    }

    private static Reach reach(List<List<Measurement>> curves, double rmse, ToDoubleFunction<Measurement> time) {
        double millis = Double.NaN;
        boolean bound = false;
        for (List<Measurement> curve : curves) {
            OptionalDouble reach = timeToReach(curve, rmse, time);
            if (reach.isPresent() && !(reach.getAsDouble() >= millis)) {
                millis = reach.getAsDouble();
                // the curve's cheapest setting already below that error: its time is an upper bound of ours there
                bound = ordered(curve).get(0).rmse() <= rmse;
            }
        }
        return new Reach(millis, bound);
    }
}

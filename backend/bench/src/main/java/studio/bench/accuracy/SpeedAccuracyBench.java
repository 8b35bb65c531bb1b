package studio.bench.accuracy;

import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

import studio.engine.render.Film;
import studio.engine.render.RenderResult;
import studio.engine.render.RenderSettings;
import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.engine.sampler.Sampler;
import studio.engine.scene.Scene;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.format.SceneDefaults;

/**
 * Measures one scene: a reference render with many jittered samples, then every available sampler
 * at each sample count and (if the engine has it) adaptive sampling at each threshold on top of
 * sobol, or else of the best of those samplers, timed in rounds. Every render reuses the compiled
 * scene and its settings with only the sampler (and threshold) swapped, and runs on all cores.
 */
final class SpeedAccuracyBench {

    /** The reference's sampler. */
    static final String REFERENCE_SAMPLER = "jittered";
    /** Added to the scene's seed for the reference, so its noise is independent of the measured renders'. */
    static final long REFERENCE_SEED_OFFSET = 0x5EED_0001L;

    /**
     * @param runs               timed renders per setting, one per round; the median counts (warm-up renders per scene come first)
     * @param referenceSamples   samples per pixel of the reference
     * @param sampleCounts       the fixed counts per pixel to measure
     * @param thresholds         the adaptive thresholds to measure
     * @param adaptiveMaxSamples the most samples adaptive sampling may spend on a pixel
     */
    record Config(int runs, int referenceSamples, List<Integer> sampleCounts, List<Double> thresholds,
                  int adaptiveMaxSamples, double defaultThreshold, List<Integer> defaultSampleCounts) {

        /**
         * Fixed counts 1 to 256; thresholds 0.5 to 0.01 at 256 samples at most; and the default
         * threshold at 1 to 64 samples at most (the default sampling as {@code render.samples} moves it).
         */
        static Config defaults(int runs, int referenceSamples) {
            return new Config(runs, referenceSamples, List.of(1, 4, 16, 64, 256),
                    List.of(0.5, 0.3, 0.2, 0.1, 0.05, 0.02, 0.01), 256, SceneDefaults.ADAPTIVE,
                    List.of(1, 2, 4, 8, 16, 32, 64));
        }

        /** These settings with {@code values} as the adaptive thresholds (null: as they are). */
        Config withThresholds(List<Double> values) {
            return values == null ? this : new Config(runs, referenceSamples, sampleCounts, values, adaptiveMaxSamples,
                    defaultThreshold, defaultSampleCounts);
        }
    }

    /** One scene's results: its rows and its reference image. */
    record SceneResult(String scene, List<Measurement> rows, Film reference, double referenceMillis) {
    }

    private final Config config;
    private final PrintStream log;

    SpeedAccuracyBench(Config config, PrintStream log) {
        this.config = config;
        this.log = log;
    }

    SceneResult run(String name, CompiledScene compiled) {
        return run(name, compiled, null);
    }

    /**
     * As {@link #run(String, CompiledScene)}, with POV-Ray's settings of the scene (or null) timed in
     * the same rounds, each round right after ours, and their rows added.
     */
    SceneResult run(String name, CompiledScene compiled, PovrayAccuracy.Scene povray) {
        SceneResult ours = runOurs(name, compiled, povray);
        if (povray == null) {
            return ours;
        }
        List<Measurement> rows = new ArrayList<>(ours.rows());
        rows.addAll(povray.rows());
        return new SceneResult(name, rows, ours.reference(), ours.referenceMillis());
    }

    private SceneResult runOurs(String name, CompiledScene compiled, PovrayAccuracy.Scene povray) {
        Scene scene = compiled.scene();
        RenderSettings base = compiled.settings();
        boolean adaptive = EngineFeatures.hasAdaptive();

        warmUp(scene, base);

        RenderSettings referenceSettings = settings(base,
                EngineFeatures.sampler(REFERENCE_SAMPLER, config.referenceSamples()).orElseThrow(), Double.NaN,
                base.seed() + REFERENCE_SEED_OFFSET, adaptive);
        long start = System.nanoTime();
        Film reference = Renderer.render(RenderRequest.of(scene, referenceSettings)).film();
        double referenceMillis = (System.nanoTime() - start) / 1e6;
        log.printf(Locale.ROOT, "%s: reference, %s at %d samples/pixel, %.0f ms%n", name, REFERENCE_SAMPLER,
                config.referenceSamples(), referenceMillis);

        List<Measurement> rows = new ArrayList<>(measure(name, oneRoundPlans(base), scene, reference, povray));
        if (adaptive && !adaptiveAccepts(base, "sobol")) {
            // an engine whose adaptive sampling does not walk sobol: on top of the sampler that did best
            String best = bestSampler(rows, base);
            if (best != null) {
                rows.addAll(measure(name, adaptivePlans(best, base), scene, reference, null));
            }
        }
        return new SceneResult(name, rows, reference, referenceMillis);
    }

    /**
     * The settings timed in the same rounds: every fixed count, and, where the engine has adaptive
     * sampling on sobol (which walks one stratified sequence, see Renderer), its two curves, so that
     * the ratios between them all see the same machine.
     */
    private List<Planned> oneRoundPlans(RenderSettings base) {
        List<Planned> plans = new ArrayList<>(fixedPlans(base));
        if (EngineFeatures.hasAdaptive() && adaptiveAccepts(base, "sobol")) {
            plans.addAll(adaptivePlans("sobol", base));
            plans.addAll(bySamplesPlans("sobol", base));
        }
        return plans;
    }

    /** A setting to measure. */
    private record Planned(Method method, int samples, RenderSettings settings) {
    }

    /**
     * Only the times of one scene, for another JVM's share of the rounds ({@code --forks}): the same
     * warm-up and the same settings as {@link #run} (the fixed counts and adaptive sampling on sobol),
     * timed in the same rounds, with POV-Ray's settings (or null) after ours in each round as there,
     * without a reference, so each row's error is NaN.
     */
    List<Measurement> timesOnly(String name, CompiledScene compiled, PovrayAccuracy.Scene povray) {
        Scene scene = compiled.scene();
        RenderSettings base = compiled.settings();
        warmUp(scene, base);
        List<Measurement> rows = new ArrayList<>(measure(name, oneRoundPlans(base), scene, null, povray));
        if (povray != null) {
            rows.addAll(povray.rows());
        }
        return rows;
    }

    /** Lets the JIT compile the hot loops (fixed and adaptive) before anything is timed. */
    private void warmUp(Scene scene, RenderSettings base) {
        boolean adaptive = EngineFeatures.hasAdaptive();
        for (int i = 0; i < 3; i++) {
            Renderer.render(RenderRequest.of(scene, settings(base, EngineFeatures.sampler(REFERENCE_SAMPLER, 16).orElseThrow(),
                    Double.NaN, base.seed(), adaptive)));
            if (adaptive && adaptiveAccepts(base, "sobol")) {
                Renderer.render(RenderRequest.of(scene, settings(base, EngineFeatures.sampler("sobol", 64).orElseThrow(), 0.1,
                        base.seed(), true)));
            }
        }
    }

    /** Every sampler the engine has at each of the configured counts. */
    private List<Planned> fixedPlans(RenderSettings base) {
        boolean adaptive = EngineFeatures.hasAdaptive();
        List<Planned> fixed = new ArrayList<>();
        for (String samplerName : EngineFeatures.SAMPLER_NAMES) {
            for (int n : config.sampleCounts()) {
                Optional<Sampler> sampler = EngineFeatures.sampler(samplerName, n);
                if (sampler.isPresent()) {
                    fixed.add(new Planned(Method.fixed(samplerName), n,
                            settings(base, sampler.get(), Double.NaN, base.seed(), adaptive)));
                }
            }
        }
        return fixed;
    }

    private List<Planned> adaptivePlans(String samplerName, RenderSettings base) {
        Sampler sampler = EngineFeatures.sampler(samplerName, config.adaptiveMaxSamples()).orElseThrow();
        List<Planned> plans = new ArrayList<>();
        for (double threshold : config.thresholds()) {
            plans.add(new Planned(Method.adaptive(samplerName, threshold), config.adaptiveMaxSamples(),
                    settings(base, sampler, threshold, base.seed(), true)));
        }
        return plans;
    }

    /** The default threshold at each of the configured most samples a pixel may take. */
    private List<Planned> bySamplesPlans(String samplerName, RenderSettings base) {
        List<Planned> plans = new ArrayList<>();
        for (int n : config.defaultSampleCounts()) {
            Sampler sampler = EngineFeatures.sampler(samplerName, n).orElseThrow();
            plans.add(new Planned(Method.adaptiveBySamples(samplerName, config.defaultThreshold()), n,
                    settings(base, sampler, config.defaultThreshold(), base.seed(), true)));
        }
        return plans;
    }

    /**
     * The sampler adaptive sampling builds on: the fixed-count sampler that reaches the target error
     * (jittered's at 16 samples) soonest, among those the engine accepts for adaptive sampling at the
     * adaptive maximum (not the regular one: every batch would land on the same grid); if none reaches
     * it, the one with the lowest error at its most samples.
     */
    String bestSampler(List<Measurement> rows, RenderSettings base) {
        BenchSummary.Target target = BenchSummary.target(rows);
        String best = null;
        double bestTime = Double.POSITIVE_INFINITY, bestError = Double.POSITIVE_INFINITY;
        for (String samplerName : EngineFeatures.SAMPLER_NAMES) {
            List<Measurement> own = rows.stream().filter(m -> m.method().equals(samplerName)).toList();
            if (own.isEmpty() || !adaptiveAccepts(base, samplerName)) {
                continue;
            }
            double time = target == null ? Double.NaN : BenchSummary.timeToReach(own, target.rmse()).orElse(Double.NaN);
            double error = own.get(own.size() - 1).rmse();
            boolean better = !Double.isNaN(time)
                    ? time < bestTime
                    : bestTime == Double.POSITIVE_INFINITY && error < bestError;
            if (better) {
                best = samplerName;
                if (!Double.isNaN(time)) {
                    bestTime = time;
                }
                bestError = error;
            }
        }
        return best;
    }

    /** True if the engine takes this sampler at the adaptive maximum with a threshold. */
    private boolean adaptiveAccepts(RenderSettings base, String samplerName) {
        Optional<Sampler> sampler = EngineFeatures.sampler(samplerName, config.adaptiveMaxSamples());
        if (sampler.isEmpty()) {
            return false;
        }
        try {
            settings(base, sampler.get(), config.thresholds().get(0), base.seed(), true);
            return true;
        } catch (IllegalArgumentException e) {
            return false;
        }
    }

    /**
     * Times every setting {@code runs} times in rounds (each round renders every setting once, a
     * short one a few times: see {@link RoundTiming}), so a slow spell of the machine, which here
     * lasts from seconds to minutes, falls on all settings alike instead of on the few measured
     * during it; the median of each setting's rounds counts. Errors come
     * from the first round (the same seed gives the same pixels on every run; NaN without a
     * {@code reference}). POV-Ray's settings (if {@code povray} is not null) are rendered after ours in
     * each round.
     */
    private List<Measurement> measure(String scene, List<Planned> plans, Scene world, Film reference,
                                      PovrayAccuracy.Scene povray) {
        double[][] millis = new double[plans.size()][config.runs()];
        double[][] cpuMillis = new double[plans.size()][config.runs()];
        double[] rmse = new double[plans.size()], meanSpp = new double[plans.size()];
        warmUpRound(scene, plans, world);
        for (int run = 0; run < config.runs(); run++) {
            log.printf(Locale.ROOT, "%s: round %d of %d, %d settings%n", scene, run + 1, config.runs(), plans.size());
            for (int i = 0; i < plans.size(); i++) {
                RenderSettings settings = plans.get(i).settings();
                RoundTiming timing = RoundTiming.of(() -> Renderer.render(RenderRequest.of(world, settings)));
                millis[i][run] = timing.millis();
                cpuMillis[i][run] = timing.cpuMillis();
                if (run == 0) {
                    RenderResult result = timing.first();
                    rmse[i] = reference == null ? Double.NaN : ImageError.rmse(result.film(), reference);
                    meanSpp[i] = (double) EngineFeatures.samplesTaken(result, settings)
                            / (settings.width() * settings.height());
                }
            }
            if (povray != null) {
                try {
                    povray.round();
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            }
        }
        List<Measurement> rows = new ArrayList<>();
        for (int i = 0; i < plans.size(); i++) {
            Planned plan = plans.get(i);
            Method method = plan.method();
            Measurement m = new Measurement(scene, method.name(), plan.samples(), meanSpp[i], median(millis[i]),
                    median(cpuMillis[i]), rmse[i],
                    Double.isNaN(rmse[i]) ? Double.NaN : ImageError.psnr(rmse[i]), method.adaptiveThreshold());
            log.printf(Locale.ROOT, "%s: %-20s %4d spp (mean %6.1f) %9.1f ms  rmse %.5f  psnr %5.2f dB%n", scene,
                    method.isAdaptive() ? method.name() + " " + method.adaptiveThreshold() : method.name(),
                    plan.samples(), meanSpp[i], m.medianMillis(), rmse[i], m.psnr());
            rows.add(m);
        }
        return rows;
    }

    /**
     * Renders every setting once, untimed, as JMH's warm-up iterations do: otherwise the first
     * timed round also times the JIT compiling each setting's code beside the render threads.
     */
    private void warmUpRound(String scene, List<Planned> plans, Scene world) {
        log.printf(Locale.ROOT, "%s: warm-up round, %d settings%n", scene, plans.size());
        for (Planned plan : plans) {
            Renderer.render(RenderRequest.of(world, plan.settings()));
        }
    }

    /** The settings with the sampler, the seed and (if the engine has it) the adaptive threshold swapped. */
    private static RenderSettings settings(RenderSettings base, Sampler sampler, double threshold, long seed,
                                           boolean engineHasAdaptive) {
        Map<String, Object> changes = new LinkedHashMap<>();
        changes.put("sampler", sampler);
        changes.put("seed", seed);
        if (engineHasAdaptive) {
            changes.put(EngineFeatures.ADAPTIVE_THRESHOLD, Double.isNaN(threshold) ? 0.0 : threshold);
        }
        return EngineFeatures.with(base, changes);
    }

    static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }
}

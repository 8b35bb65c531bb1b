package studio.bench.accuracy;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

class BenchSummaryTest {

    /**
     * A method whose time is proportional to samples and whose error falls as samples^slope; its CPU
     * time is twice its wall time (two threads).
     */
    private static List<Measurement> method(String name, double msPerSample, double error1, double slope) {
        return method(name, msPerSample, 2 * msPerSample, error1, slope);
    }

    private static List<Measurement> method(String name, double msPerSample, double cpuMsPerSample, double error1,
                                            double slope) {
        List<Measurement> rows = new ArrayList<>();
        for (int n : new int[] {1, 4, 16, 64, 256}) {
            double rmse = error1 * Math.pow(n, slope);
            rows.add(new Measurement("s", name, n, n, msPerSample * n, cpuMsPerSample * n, rmse, ImageError.psnr(rmse),
                    Double.NaN));
        }
        return rows;
    }

    @Test
    void theCpuRatioComesFromCpuTimes() {
        List<Measurement> rows = new ArrayList<>(method("jittered", 2, 4, 0.1, -0.75));
        // sobol reaches the target at n = 8 (see below): 24 ms of wall time, 96 ms of CPU time
        rows.addAll(method("sobol", 3, 12, 0.1, -1.0));
        BenchSummary.Line sobol = BenchSummary.lines(rows, List.of()).get(1);
        assertThat(sobol.ratio()).isCloseTo(0.75, within(1e-12));
        assertThat(sobol.cpuRatio()).isCloseTo(96.0 / 64, within(1e-12));
        assertThat(BenchSummary.format("s", rows, List.of())).contains("by CPU time").contains("1.50");
    }

    @Test
    void ratiosToJitteredArePairedByJvm() {
        // sobol takes 0.75 of jittered's time to the target in each JVM; the second JVM is twice as slow
        // throughout, and the third only while it rendered jittered (a slow spell, or worse compiled code)
        List<Measurement> first = new ArrayList<>(method("jittered", 2, 0.1, -0.75));
        first.addAll(method("sobol", 3, 0.1, -1.0));
        List<Measurement> second = new ArrayList<>(method("jittered", 4, 0.1, -0.75));
        second.addAll(method("sobol", 6, 0.1, -1.0));
        List<Measurement> third = new ArrayList<>(method("jittered", 4, 0.1, -0.75));
        third.addAll(method("sobol", 3, 0.1, -1.0));
        // the medians over the JVMs: jittered 4 ms a sample, sobol 3
        List<Measurement> medians = new ArrayList<>(method("jittered", 4, 0.1, -0.75));
        medians.addAll(method("sobol", 3, 0.1, -1.0));

        assertThat(BenchSummary.lines(medians, List.of()).get(1).ratio()).isCloseTo(0.375, within(1e-12));
        BenchSummary.Line sobol = BenchSummary.lines(medians, List.of(first, second, third)).get(1);
        assertThat(sobol.ratio()).isCloseTo(0.75, within(1e-12));
        assertThat(sobol.cpuRatio()).isCloseTo(0.75, within(1e-12));
        assertThat(sobol.millis()).as("the time itself is still the medians'").isCloseTo(24, within(1e-9));
        assertThat(BenchSummary.format("s", medians, List.of(first, second, third))).contains("0.75").doesNotContain("0.38");
    }

    @Test
    void aMethodTimedInOneJvmOnlyTakesThatJvmsRatio() {
        List<Measurement> first = new ArrayList<>(method("jittered", 2, 0.1, -0.75));
        first.addAll(method("povray-grid", 4, 0.1, -0.75));
        List<Measurement> second = method("jittered", 4, 0.1, -0.75);

        BenchSummary.Line povray = BenchSummary.lines(first, List.of(first, second)).get(1);

        assertThat(povray.ratio()).isCloseTo(2, within(1e-12));
    }

    @Test
    void targetIsJitteredAtSixteenSamples() {
        List<Measurement> rows = method("jittered", 2, 0.1, -0.75);
        BenchSummary.Target target = BenchSummary.target(rows);
        assertThat(target.rmse()).isCloseTo(0.1 * Math.pow(16, -0.75), within(1e-15));
        assertThat(target.millis()).isEqualTo(32);
    }

    @Test
    void linesGiveSlopesTimesToTargetAndRatios() {
        List<Measurement> rows = new ArrayList<>(method("jittered", 2, 0.1, -0.75));
        rows.addAll(method("random", 2, 0.1, -0.5));
        rows.addAll(method("sobol", 3, 0.1, -1.0));
        List<BenchSummary.Line> lines = BenchSummary.lines(rows, List.of());
        assertThat(lines).extracting(BenchSummary.Line::method).containsExactly("jittered", "random", "sobol");

        BenchSummary.Line jittered = lines.get(0), random = lines.get(1), sobol = lines.get(2);
        assertThat(jittered.slope()).isCloseTo(-0.75, within(1e-12));
        assertThat(jittered.millis()).isCloseTo(32, within(1e-9));
        assertThat(jittered.ratio()).isCloseTo(1, within(1e-12));

        // random: 0.1 n^-0.5 = 0.1 * 16^-0.75 at n = 64: 128 ms
        assertThat(random.slope()).isCloseTo(-0.5, within(1e-12));
        assertThat(random.millis()).isCloseTo(128, within(1e-9));
        assertThat(random.ratio()).isCloseTo(4, within(1e-12));

        // sobol: 0.1 / n = 0.1 / 8 at n = 8, between the measured 4 and 16: 24 ms
        assertThat(sobol.millis()).isCloseTo(24, within(1e-9));
        assertThat(sobol.ratio()).isCloseTo(0.75, within(1e-12));
        assertThat(sobol.upperBound()).isFalse();
        assertThat(sobol.samples()).as("samples to the target, by no clock").isCloseTo(8, within(1e-9));
        assertThat(random.samples()).isCloseTo(64, within(1e-9));
        assertThat(jittered.samples()).isCloseTo(16, within(1e-9));
        assertThat(BenchSummary.format("s", rows, List.of())).contains("spp to target").contains("8.00");
    }

    @Test
    void adaptiveSlopeIsAgainstTheMeanSamplesOverEveryThreshold() {
        List<Measurement> rows = new ArrayList<>(method("jittered", 2, 0.1, -0.75));
        double[] meanSpp = {2, 5, 11, 30, 70};
        for (int i = 0; i < meanSpp.length; i++) {
            double rmse = 0.05 * Math.pow(meanSpp[i], -1.25);
            rows.add(new Measurement("s", "adaptive-jittered", 256, meanSpp[i], meanSpp[i], 2 * meanSpp[i], rmse,
                    ImageError.psnr(rmse), 0.2 / (i + 1)));
        }
        BenchSummary.Line adaptive = BenchSummary.lines(rows, List.of()).get(1);
        assertThat(adaptive.slope()).isCloseTo(-1.25, within(1e-12));
        assertThat(BenchSummary.format("s", rows, List.of())).contains("adaptive-jittered", "-1.25", "target RMSE");
    }

    @Test
    void aMethodNeverReachingTheTargetSaysSo() {
        List<Measurement> rows = new ArrayList<>(method("jittered", 2, 0.1, -0.75));
        rows.addAll(method("regular", 2, 0.5, -0.1));
        BenchSummary.Line regular = BenchSummary.lines(rows, List.of()).get(1);
        assertThat(regular.millis()).isNaN();
        assertThat(BenchSummary.format("s", rows, List.of())).contains("not reached");
    }

    @Test
    void comparesOurDefaultWithEachPovRaySetting() {
        List<Measurement> rows = new ArrayList<>(method("adaptive-sobol", 1, 0.1, -1.0));
        // POV-Ray: twice our time per sample, at the same errors, so our time to each error is half of its
        rows.addAll(method("povray-grid", 2, 0.1, -1.0).subList(1, 5));
        String text = BenchSummary.againstPovray(rows);
        assertThat(text).contains("adaptive-sobol against POV-Ray").contains("0.50").contains("worst ratio 0.50");
        // an error below our default's range is said to be so, and does not count
        rows.add(new Measurement("s", "povray-adaptive", 81, 40, 100, Double.NaN, 1e-6, ImageError.psnr(1e-6), 0.01));
        assertThat(BenchSummary.againstPovray(rows)).contains("below our default's range").contains("worst ratio 0.50");
        assertThat(BenchSummary.againstPovray(method("adaptive-sobol", 1, 0.1, -1.0))).isEmpty();
    }

    @Test
    void comparesByCpuTimeWherePovRaysCpuTimeWasMeasured() {
        // ours: 1 ms a sample by the wall, 2 of CPU; POV-Ray: 2 ms a sample by the wall, 8 of CPU
        List<Measurement> rows = new ArrayList<>(method("adaptive-sobol", 1, 2, 0.1, -1.0));
        rows.addAll(method("povray-grid", 2, 8, 0.1, -1.0).subList(1, 5));
        String text = BenchSummary.againstPovray(rows);
        assertThat(text).contains("(by CPU time)").contains("0.50 (0.25)").contains("worst ratio 0.50 (by CPU time 0.25)");
        // without POV-Ray's CPU time (an older CSV): the wall's ratios alone
        List<Measurement> wallOnly = new ArrayList<>(method("adaptive-sobol", 1, 2, 0.1, -1.0));
        wallOnly.add(new Measurement("s", "povray-grid", 16, 16, 32, Double.NaN, 0.1 / 16, ImageError.psnr(0.1 / 16),
                Double.NaN));
        assertThat(BenchSummary.againstPovray(wallOnly)).contains("ms  0.50\n").contains("worst ratio 0.50\n")
                .doesNotContain("(0.");
    }

    @Test
    void ourDefaultIsTheLowerOfItsCurveByThresholdAndItsCurveBySamples() {
        // by threshold: the cheapest setting takes 4 samples (errors 0.1/4 .. 0.1/256 at 1 ms a sample)
        List<Measurement> rows = new ArrayList<>(method("adaptive-sobol", 1, 0.1, -1.0).subList(1, 5));
        // by samples: from one sample a pixel, at 1 ms a sample too but twice the error, so it reaches
        // POV-Ray's 1-ray error at 2 samples, 2 ms
        rows.addAll(method(BenchSummary.DEFAULT_BY_SAMPLES, 1, 0.2, -1.0));
        rows.addAll(method("povray-grid", 4, 0.1, -1.0).subList(0, 2));
        String text = BenchSummary.againstPovray(rows);
        assertThat(text).contains("by threshold and by samples");
        // at POV-Ray's 1 ray (error 0.1, 4 ms) ours takes 2 ms: 0.50, not the "<= 1.00" the threshold curve alone gives
        assertThat(text).contains("rmse 0.10000       4.0 ms  0.50");
        List<Measurement> thresholdOnly = new ArrayList<>(rows.subList(0, 4));
        thresholdOnly.addAll(rows.subList(9, 11));
        assertThat(BenchSummary.againstPovray(thresholdOnly)).contains("rmse 0.10000       4.0 ms  <= 1.00");
    }
}

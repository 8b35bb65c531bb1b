package studio.bench.accuracy;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.api.Test;

class ForksTest {

    private static Measurement row(String method, int samples, double threshold, double millis, double cpu, double rmse) {
        return new Measurement("edges", method, samples, samples, millis, cpu, rmse, -20 * Math.log10(rmse), threshold);
    }

    @Test
    void eachTimeBecomesTheMedianOverTheJvmsAndTheErrorsStayTheFirstJvms() {
        List<Measurement> first = List.of(row("jittered", 16, Double.NaN, 80, 150, 0.0027),
                row("adaptive-sobol", 256, 0.05, 40, 70, 0.0020),
                row("povray-adaptive", 1, 0.3, 10, Double.NaN, 0.003));
        List<Measurement> second = List.of(row("jittered", 16, Double.NaN, 100, 190, Double.NaN),
                row("adaptive-sobol", 256, 0.05, 30, 60, Double.NaN),
                row("adaptive-sobol", 256, 0.1, 1, 1, Double.NaN));
        List<Measurement> third = List.of(row("jittered", 16, Double.NaN, 90, 160, Double.NaN),
                row("adaptive-sobol", 256, 0.05, 50, 65, Double.NaN));

        List<Measurement> merged = Forks.merge(first, List.of(second, third));

        assertThat(merged).hasSize(3);
        assertThat(merged.get(0).medianMillis()).isEqualTo(90);
        assertThat(merged.get(0).medianCpuMillis()).isEqualTo(160);
        assertThat(merged.get(0).rmse()).isEqualTo(0.0027);
        // another threshold's row does not count for 0.05
        assertThat(merged.get(1).medianMillis()).isEqualTo(40);
        assertThat(merged.get(1).medianCpuMillis()).isEqualTo(65);
        assertThat(merged.get(1).rmse()).isEqualTo(0.0020);
        // a row no fork measured (POV-Ray, when the forks ran without it) is the first JVM's
        assertThat(merged.get(2)).isEqualTo(first.get(2));
    }

    @Test
    void povRaysRowsTimedInTheForksTakeTheMedianOverTheJvmsToo() {
        List<Measurement> first = List.of(row("povray-grid", 1, Double.NaN, 43, 80, 0.03));
        List<Measurement> second = List.of(row("povray-grid", 1, Double.NaN, 25, 48, Double.NaN));
        List<Measurement> third = List.of(row("povray-grid", 1, Double.NaN, 30, 55, Double.NaN));

        List<Measurement> merged = Forks.merge(first, List.of(second, third));

        assertThat(merged).containsExactly(row("povray-grid", 1, Double.NaN, 30, 55, 0.03));
    }

    @Test
    void eachJvmsRowsTakeTheFirstJvmsErrors() {
        List<Measurement> first = List.of(row("jittered", 16, Double.NaN, 80, 150, 0.0027),
                row("adaptive-sobol", 256, 0.05, 40, 70, 0.0020));
        List<Measurement> second = List.of(row("jittered", 16, Double.NaN, 100, 190, Double.NaN),
                row("adaptive-sobol", 256, 0.1, 1, 1, Double.NaN));

        List<List<Measurement>> jvms = Forks.withFirstErrors(first, List.of(second));

        assertThat(jvms).hasSize(2);
        assertThat(jvms.get(0)).isEqualTo(first);
        // the second JVM's own times, the first JVM's error; a threshold the first did not measure is left out
        assertThat(jvms.get(1)).containsExactly(row("jittered", 16, Double.NaN, 100, 190, 0.0027));
    }

    @Test
    void eachJvmsRowsAreWrittenWithItsNumber() {
        List<Measurement> first = List.of(row("jittered", 16, Double.NaN, 80, 150, 0.0027));
        List<Measurement> second = List.of(row("jittered", 16, Double.NaN, 100, 190, 0.0027));

        String csv = BenchCsv.formatByJvm(List.of(first, second));

        assertThat(csv.lines().toList()).containsExactly("jvm," + BenchCsv.HEADER,
                "1," + BenchCsv.format(first).lines().skip(1).findFirst().orElseThrow(),
                "2," + BenchCsv.format(second).lines().skip(1).findFirst().orElseThrow());
    }

    @Test
    void theCsvReadsBackWhatItWrote() {
        List<Measurement> rows = List.of(row("jittered", 16, Double.NaN, 80.5, 150.25, 0.0027),
                row("adaptive-sobol", 256, 0.05, 40, 70, Double.NaN),
                row("povray-grid", 4, Double.NaN, 12, Double.NaN, 0.01));

        List<Measurement> read = BenchCsv.parse(BenchCsv.format(rows));

        assertThat(read).hasSize(3);
        assertThat(read.get(0).medianMillis()).isEqualTo(80.5);
        assertThat(read.get(0).medianCpuMillis()).isEqualTo(150.25);
        assertThat(read.get(0).threshold()).isNaN();
        assertThat(read.get(1).threshold()).isEqualTo(0.05);
        assertThat(read.get(1).rmse()).isNaN();
        assertThat(read.get(2).medianCpuMillis()).isNaN();
    }
}

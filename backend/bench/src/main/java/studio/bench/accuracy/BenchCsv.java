package studio.bench.accuracy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/** The measurements as CSV, one row each, numbers in the C locale. */
final class BenchCsv {

    static final String HEADER = "scene,method,samples,mean_spp,median_ms,median_cpu_ms,rmse,psnr_db,threshold";

    private BenchCsv() {
    }

    static String format(List<Measurement> rows) {
        StringBuilder csv = new StringBuilder(HEADER).append('\n');
        for (Measurement m : rows) {
            csv.append(String.format(Locale.ROOT, "%s,%s,%d,%.3f,%.3f,%s,%.6g,%.3f,%s\n", m.scene(), m.method(),
                    m.samples(), m.meanSamplesPerPixel(), m.medianMillis(),
                    Double.isNaN(m.medianCpuMillis()) ? "" : String.format(Locale.ROOT, "%.3f", m.medianCpuMillis()),
                    m.rmse(), m.psnr(),
                    Double.isNaN(m.threshold()) ? "" : String.format(Locale.ROOT, "%s", m.threshold())));
        }
        return csv.toString();
    }

    static void write(Path file, List<Measurement> rows) throws IOException {
        Files.writeString(file, format(rows));
    }
}

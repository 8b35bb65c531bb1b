package studio.bench.accuracy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** The measurements as CSV, one row each, numbers in the C locale. */
final class BenchCsv {

    static final String HEADER = "scene,method,samples,mean_spp,median_ms,median_cpu_ms,rmse,psnr_db,threshold";

    private BenchCsv() {
    }

    static String format(List<Measurement> rows) {
        StringBuilder csv = new StringBuilder(HEADER).append('\n');
        rows.forEach(m -> csv.append(line(m)).append('\n'));
        return csv.toString();
    }

    /** One row's fields, in the order of {@link #HEADER}. */
    private static String line(Measurement m) {
        return String.format(Locale.ROOT, "%s,%s,%d,%.3f,%.3f,%s,%.6g,%.3f,%s", m.scene(), m.method(),
                m.samples(), m.meanSamplesPerPixel(), m.medianMillis(),
                Double.isNaN(m.medianCpuMillis()) ? "" : String.format(Locale.ROOT, "%.3f", m.medianCpuMillis()),
                m.rmse(), m.psnr(),
                Double.isNaN(m.threshold()) ? "" : String.format(Locale.ROOT, "%s", m.threshold()));
    }

    static void write(Path file, List<Measurement> rows) throws IOException {
        Files.writeString(file, format(rows));
    }

    /** Each JVM's rows, numbered from 1 in a first column {@code jvm}, in the format of {@link #format}. */
    static String formatByJvm(List<List<Measurement>> jvms) {
        StringBuilder csv = new StringBuilder("jvm,").append(HEADER).append('\n');
        for (int k = 0; k < jvms.size(); k++) {
            for (Measurement m : jvms.get(k)) {
                csv.append(k + 1).append(',').append(line(m)).append('\n');
            }
        }
        return csv.toString();
    }

    /** The rows {@link #format} wrote (an empty CPU time or threshold reads as NaN). */
    static List<Measurement> parse(String csv) {
        List<Measurement> rows = new ArrayList<>();
        String[] lines = csv.split("\n");
        if (lines.length == 0 || !lines[0].equals(HEADER)) {
            throw new IllegalArgumentException("not the benchmark's CSV: " + (lines.length == 0 ? "" : lines[0]));
        }
        for (int i = 1; i < lines.length; i++) {
            String[] f = lines[i].split(",", -1);
            if (f.length != 9) {
                throw new IllegalArgumentException("line " + (i + 1) + " has " + f.length + " fields, not 9: " + lines[i]);
            }
            rows.add(new Measurement(f[0], f[1], Integer.parseInt(f[2]), Double.parseDouble(f[3]),
                    Double.parseDouble(f[4]), orNaN(f[5]), Double.parseDouble(f[6]), Double.parseDouble(f[7]), orNaN(f[8])));
        }
        return rows;
    }

    static List<Measurement> read(Path file) throws IOException {
        return parse(Files.readString(file));
    }

    private static double orNaN(String field) {
        return field.isEmpty() ? Double.NaN : Double.parseDouble(field);
    }
}

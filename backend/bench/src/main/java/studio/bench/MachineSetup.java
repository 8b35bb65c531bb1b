package studio.bench;

import java.io.IOException;
import java.nio.file.Path;
import java.time.LocalDate;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;

/** What the benchmark ran on, for its report: date, cores, and the JVM's, POV-Ray's and Sunflow's versions. */
final class MachineSetup {

    private MachineSetup() {
    }

    /** One paragraph on the machine, the renderers' versions and the settings. */
    static String describe(Path java, Path povray, Path sunflowJar, Renderers r, int runs) {
        return String.format(Locale.ROOT, "%s, %d cores (%s %s), Java %s (%s), %s, Sunflow %s. Ours %s. %dx%d, %d threads "
                        + "each; median of %d runs, the three renderers alternated in a rotating order.", LocalDate.now(),
                Runtime.getRuntime().availableProcessors(), System.getProperty("os.name"), System.getProperty("os.arch"),
                javaVersion(java), java, povrayVersion(povray), sunflowVersion(sunflowJar), ours(r), r.width(), r.height(),
                r.threads(), runs);
    }

    /** How ours was started: through the launcher (its start-up cache, the newest JDK) or as java -jar. */
    static String ours(Renderers r) {
        return r.launcher() != null ? "through " + r.launcher() : "as java -jar, without bin/studio's start-up cache";
    }

    private static String javaVersion(Path java) {
        String v = firstLineOf(List.of(java.toString(), "-version"));
        return v.replaceAll(".*\"(.*)\".*", "$1");
    }

    private static String povrayVersion(Path povray) {
        try {
            Process p = new ProcessBuilder(povray.toString(), "--version").redirectErrorStream(true).start();
            String text = new String(p.getInputStream().readAllBytes());
            p.waitFor(10, TimeUnit.SECONDS);
            return Arrays.stream(text.split("\n")).filter(l -> l.startsWith("POV-Ray")).findFirst().orElse("POV-Ray ?")
                    .trim();
        } catch (IOException e) {
            return "POV-Ray ?";
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "POV-Ray ?";
        }
    }

    private static String sunflowVersion(Path jar) {
        Path real = jar;
        try {
            real = jar.toRealPath();
        } catch (IOException e) {
            // keep the name as given
        }
        String version = real.getFileName().toString().replaceAll("^sunflow-?", "").replaceAll("\\.jar$", "");
        return version.isEmpty() ? "?" : version;
    }

    private static String firstLineOf(List<String> command) {
        try {
            Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
            String text = new String(p.getInputStream().readAllBytes());
            p.waitFor(10, TimeUnit.SECONDS);
            return text.lines().findFirst().orElse("?");
        } catch (IOException e) {
            return "?";
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "?";
        }
    }
}

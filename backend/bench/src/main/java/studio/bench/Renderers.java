package studio.bench;

import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The command lines of the three renderers, at the benchmark's image size and thread count. Each
 * renders one scene file to one PNG as a whole process, start-up included.
 *
 * @param java         the JVM for ours and for Sunflow
 * @param benchClasses where {@link SunflowRender} is (this module's jar or classes folder)
 */
record Renderers(Path java, Path studioJar, Path povray, Path sunflowJar, Path benchClasses, int width, int height,
                 int threads, Path launcher) {

    /** Ours as {@code java -jar studio.jar}, without the launcher. */
    Renderers(Path java, Path studioJar, Path povray, Path sunflowJar, Path benchClasses, int width, int height,
              int threads) {
        this(java, studioJar, povray, sunflowJar, benchClasses, width, height, threads, null);
    }

    enum Peer {
        OURS("ours"), POVRAY("povray"), SUNFLOW("sunflow");

        final String label;

        Peer(String label) {
            this.label = label;
        }
    }

    /**
     * Ours through its CLI, with fixed sampling as the peers': one sample per pixel uses the
     * {@code regular} sampler (the pixel's centre, as the peers do), more the {@code jittered} one
     * on every pixel (POV-Ray's +AM1 at threshold 0 and Sunflow's fixed anti-aliasing take them all).
     */
    List<String> ours(Path sceneJson, Path out, int samples) {
        // bin/studio runs the same jar with a start-up cache (made on its first run); STUDIO_JAR names the jar
        List<String> cmd = new ArrayList<>(launcher != null
                ? List.of("env", "STUDIO_JAR=" + studioJar.toAbsolutePath(), launcher.toString())
                : List.of(java.toString(), "-jar", studioJar.toString()));
        cmd.addAll(List.of("render", sceneJson.toString(), "-o", out.toString(), "--width", Integer.toString(width),
                "--height", Integer.toString(height), "--samples", Integer.toString(samples)));
        cmd.addAll(List.of("--sampler", samples == 1 ? "regular" : "jittered"));
        cmd.addAll(List.of("--threads", Integer.toString(threads), "--quiet"));
        return cmd;
    }

    /**
     * POV-Ray: {@code -A} shoots one ray through each pixel's centre; {@code +A0.0 +AM1 +Rk} makes
     * method 1 supersample every pixel (threshold 0) with k x k rays.
     */
    List<String> povray(Path pov, Path out, int samples) {
        List<String> cmd = new ArrayList<>(List.of(povray.toString(), "+I" + pov, "+O" + out, "+W" + width,
                "+H" + height, "+WT" + threads, "-D", "-V", "+FN", "-P"));
        if (samples == 1) {
            cmd.add("-A");
        } else {
            cmd.addAll(List.of("+A0.0", "+AM1", "+R" + squareRoot(samples)));
        }
        return cmd;
    }

    /** Sunflow through {@link SunflowRender}, its classpath Sunflow's jar first, then this module's classes. */
    List<String> sunflow(Path script, Path out) {
        return List.of(java.toString(), "-cp", sunflowJar + File.pathSeparator + benchClasses,
                SunflowRender.class.getName(), script.toString(), out.toString());
    }

    /** Sunflow's anti-aliasing level for a number of samples per pixel: 4^level = samples. */
    static int sunflowAaLevel(int samples) {
        int level = 0;
        for (int n = 1; n < samples; n *= 4) {
            level++;
        }
        if (1 << (2 * level) != samples) {
            throw new IllegalArgumentException("Sunflow takes 4^k samples per pixel (1, 4, 16, 64, ...), not " + samples);
        }
        return level;
    }

    static int squareRoot(int samples) {
        int k = (int) Math.round(Math.sqrt(samples));
        if (k * k != samples) {
            throw new IllegalArgumentException("POV-Ray's grid takes k x k samples per pixel, not " + samples);
        }
        return k;
    }

    /** Checks that every renderer can take this many samples per pixel exactly. */
    static void checkSamples(int samples) {
        sunflowAaLevel(samples);
        squareRoot(samples);
    }
}

package studio.bench.accuracy;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import studio.engine.sampler.Sampler;

class BenchCommandTest {

    private final ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();

    private int run(String... args) {
        return BenchCommand.run(args, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
    }

    @Test
    void tinyRunWritesTheCsvTheChartsAndTheSummary(@TempDir Path dir) throws IOException {
        int code = run("--out", dir.toString(), "--width", "16", "--height", "12", "--runs", "1", "--forks", "2",
                "--reference-samples", "16", "--scenes", BenchSceneFiles.dir().toString(), "--no-povray");

        assertThat(code).as(err.toString(StandardCharsets.UTF_8)).isEqualTo(BenchCommand.OK);
        List<String> csv = Files.readAllLines(dir.resolve("speed-accuracy.csv"));
        assertThat(csv.get(0)).isEqualTo("scene,method,samples,mean_spp,median_ms,median_cpu_ms,rmse,psnr_db,threshold");

        long samplers = EngineFeatures.SAMPLER_NAMES.stream().filter(n -> EngineFeatures.sampler(n, 16).isPresent()).count();
        int adaptiveRows = EngineFeatures.hasAdaptive() ? 7 + 7 : 0; // by threshold, and the default threshold by samples
        int scenes = BenchSceneFiles.all().size();
        assertThat(csv).hasSize(1 + scenes * (int) (samplers * 5 + adaptiveRows));
        assertThat(csv).anySatisfy(line -> assertThat(line).startsWith("edges,jittered,16,16.000,"));
        assertThat(csv).anySatisfy(line -> assertThat(line).startsWith("stripes,regular,256,256.000,"));
        // the default threshold at one sample a pixel at most: one sample on every pixel
        assertThat(csv).anySatisfy(line -> assertThat(line).startsWith("edges,adaptive-sobol-samples,1,1.000,").endsWith(",0.05"));
        for (String line : csv.subList(1, csv.size())) {
            String[] fields = line.split(",", -1);
            assertThat(fields).hasSize(9);
            assertThat(Double.parseDouble(fields[4])).as(line).isPositive();
            assertThat(Double.parseDouble(fields[5])).as("our renders' CPU time: " + line).isPositive();
            assertThat(Double.parseDouble(fields[6])).as(line).isNotNegative();
            assertThat(fields[8].isEmpty()).as(line).isEqualTo(!fields[1].startsWith("adaptive"));
        }

        assertThat(dir.resolve("speed-accuracy.png")).isNotEmptyFile();
        // a panel a scene: about 26 KB each with the 7 scenes of scenes/bench (180 KB), 37 KB with 4
        assertThat(Files.size(dir.resolve("speed-accuracy.png"))).isLessThan(40_000L * scenes);
        assertThat(dir.resolve("speed-accuracy-edges.svg")).isNotEmptyFile();
        assertThat(dir.resolve("speed-accuracy-glass.png")).isNotEmptyFile();
        assertThat(dir.resolve("reference-stripes.png")).isNotEmptyFile();
        assertThat(Files.readString(dir.resolve("summary.txt"))).contains("soft-shadows", "target RMSE", "jittered");
        assertThat(out.toString(StandardCharsets.UTF_8)).contains("ms to target", "vs jittered", "median over 2 JVMs",
                "the median over the JVMs of each one's own ratio");
        // each JVM's own medians, both JVMs' rows, every one with the first JVM's error
        List<String> jvms = Files.readAllLines(dir.resolve("speed-accuracy-jvms.csv"));
        assertThat(jvms.get(0)).isEqualTo("jvm," + csv.get(0));
        assertThat(jvms).hasSize(1 + 2 * (csv.size() - 1));
        assertThat(jvms).anySatisfy(line -> assertThat(line).startsWith("1,edges,jittered,16,"))
                .anySatisfy(line -> assertThat(line).startsWith("2,edges,jittered,16,"));
        assertThat(jvms.subList(1, jvms.size())).allSatisfy(line -> assertThat(line.split(",", -1)[7]).isNotEqualTo("NaN"));
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("bench: JVM 2 times the same settings", "--times-only");
        // the fork's files are read and deleted, with their folder
        java.util.regex.Matcher times = java.util.regex.Pattern.compile("--times-only (\\S+),")
                .matcher(err.toString(StandardCharsets.UTF_8));
        assertThat(times.find()).isTrue();
        assertThat(Path.of(times.group(1)).getParent()).doesNotExist();
    }

    @Test
    void withPovRayASoftLitSceneHasTheAreaLightCurves(@TempDir Path dir) throws IOException {
        Path povray = Path.of("/usr/bin/povray");
        Assumptions.assumeTrue(Files.isExecutable(povray), "POV-Ray is not installed (apt-get install povray)");
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        copyAtSize("soft-ball.json", scenes, 16, 12);
        int code = run("--out", dir.resolve("out").toString(), "--runs", "1",
                "--forks", "1", "--reference-samples", "16", "--scenes", scenes.toString(), "--povray", povray.toString());

        assertThat(code).as(err.toString(StandardCharsets.UTF_8)).isEqualTo(BenchCommand.OK);
        List<String> csv = Files.readAllLines(dir.resolve("out/speed-accuracy.csv"));
        for (String method : List.of("povray-area", "povray-area-jitter", "povray-area-adaptive", "povray-area-adaptive-jitter")) {
            assertThat(csv.stream().filter(l -> l.startsWith("soft-ball," + method + ","))).hasSize(PovrayAccuracy.AREA_GRID.length);
        }
        assertThat(csv.stream().filter(l -> l.startsWith("soft-ball,povray-grid,"))).isEmpty();
    }

    @Test
    void withPovRayTheChartHasItsGridAndAdaptiveCurves(@TempDir Path dir) throws IOException {
        Path povray = Path.of("/usr/bin/povray");
        Assumptions.assumeTrue(Files.isExecutable(povray), "POV-Ray is not installed (apt-get install povray)");
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        // POV-Ray renders at the scene file's own size, as ours does
        copyAtSize("edges.json", scenes, 16, 12);
        int code = run("--out", dir.resolve("out").toString(), "--runs", "1",
                "--forks", "2", "--reference-samples", "16", "--scenes", scenes.toString(), "--povray", povray.toString());

        assertThat(code).as(err.toString(StandardCharsets.UTF_8)).isEqualTo(BenchCommand.OK);
        List<String> csv = Files.readAllLines(dir.resolve("out/speed-accuracy.csv"));
        assertThat(csv.stream().filter(l -> l.startsWith("edges,povray-grid,"))).hasSize(PovrayAccuracy.GRID.length);
        assertThat(csv.stream().filter(l -> l.startsWith("edges,povray-adaptive,"))).hasSize(PovrayAccuracy.THRESHOLDS.length);
        // one ray through each pixel's centre: one camera ray a pixel, and an error above the 64-ray grid's
        String one = csv.stream().filter(l -> l.startsWith("edges,povray-grid,1,")).findFirst().orElseThrow();
        String many = csv.stream().filter(l -> l.startsWith("edges,povray-grid,64,")).findFirst().orElseThrow();
        assertThat(Double.parseDouble(one.split(",")[3])).isEqualTo(1.0);
        assertThat(Double.parseDouble(one.split(",")[6])).isGreaterThan(Double.parseDouble(many.split(",")[6]));
        // POV-Ray's CPU seconds, as it reports them (0.000 for a render this small)
        assertThat(Double.parseDouble(one.split(",")[5])).as("POV-Ray's CPU time").isNotNegative();
        assertThat(Files.readString(dir.resolve("out/summary.txt"))).contains("against POV-Ray", "worst ratio",
                "POV-Ray's too, started by each JVM");
        // the second JVM times POV-Ray's settings too, each row with the first JVM's error
        List<String> jvms = Files.readAllLines(dir.resolve("out/speed-accuracy-jvms.csv"));
        assertThat(jvms.stream().filter(l -> l.startsWith("2,edges,povray-grid,"))).hasSize(PovrayAccuracy.GRID.length);
        assertThat(jvms.stream().filter(l -> l.startsWith("2,edges,povray-adaptive,"))).hasSize(PovrayAccuracy.THRESHOLDS.length);
        String secondOne = jvms.stream().filter(l -> l.startsWith("2,edges,povray-grid,1,")).findFirst().orElseThrow();
        assertThat(secondOne.split(",", -1)[7]).isEqualTo(one.split(",", -1)[6]);
        assertThat(Double.parseDouble(secondOne.split(",", -1)[5])).as("the second JVM's POV-Ray time").isNotNegative();
        assertThat(BenchCommand.Options.parse(new String[] {"--scenes", "s", "--povray", "/opt/povray"}).forkArguments(true))
                .containsExactly("--scenes", "s", "--runs", "2", "--povray", "/opt/povray");
    }

    @Test
    void eachSceneIsRenderedAtItsFilesOwnSizeUnlessTheCommandLineGivesOne(@TempDir Path dir) throws IOException {
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        copyAtSize("edges.json", scenes, 24, 18);
        copyAtSize("stripes.json", scenes, 16, 12);

        int code = run("--out", dir.resolve("own").toString(), "--runs", "1", "--forks", "2", "--reference-samples", "4",
                "--scenes", scenes.toString(), "--no-povray");

        assertThat(code).as(err.toString(StandardCharsets.UTF_8)).isEqualTo(BenchCommand.OK);
        assertThat(imageSize(dir.resolve("own/reference-edges.png"))).isEqualTo("24x18");
        assertThat(imageSize(dir.resolve("own/reference-stripes.png"))).isEqualTo("16x12");
        assertThat(Files.readString(dir.resolve("own/summary.txt"))).contains("edges at 24x18: target RMSE",
                "stripes at 16x12: target RMSE");
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("2 scenes (edges 24x18, stripes 16x12)");
        // the second JVM is not told a size, so it renders the files' own too
        assertThat(BenchCommand.Options.parse(new String[] {"--scenes", "s", "--runs", "3"}).forkArguments(false))
                .containsExactly("--scenes", "s", "--runs", "3", "--no-povray");

        code = run("--out", dir.resolve("given").toString(), "--width", "8", "--height", "6", "--runs", "1", "--forks", "2",
                "--reference-samples", "4", "--scenes", scenes.toString(), "--no-povray");

        assertThat(code).as(err.toString(StandardCharsets.UTF_8)).isEqualTo(BenchCommand.OK);
        assertThat(imageSize(dir.resolve("given/reference-edges.png"))).isEqualTo("8x6");
        assertThat(imageSize(dir.resolve("given/reference-stripes.png"))).isEqualTo("8x6");
        assertThat(Files.readString(dir.resolve("given/summary.txt"))).contains("edges at 8x6:", "stripes at 8x6:");
        assertThat(BenchCommand.Options.parse(new String[] {"--scenes", "s", "--width", "8", "--height", "6"}).forkArguments(false))
                .containsExactly("--scenes", "s", "--width", "8", "--height", "6", "--runs", "2", "--no-povray");
    }

    @Test
    void thresholdsReplaceTheDefaultsAndReachEveryFork() {
        BenchCommand.Options options = BenchCommand.Options.parse(new String[] {"--scenes", "s", "--thresholds", "0.01,0.005, 0.002"});

        assertThat(options.thresholds).containsExactly(0.01, 0.005, 0.002);
        assertThat(SpeedAccuracyBench.Config.defaults(1, 16).withThresholds(options.thresholds).thresholds())
                .containsExactly(0.01, 0.005, 0.002);
        assertThat(SpeedAccuracyBench.Config.defaults(1, 16).withThresholds(null).thresholds()).startsWith(0.5).endsWith(0.01);
        assertThat(options.forkArguments(false)).containsExactly("--scenes", "s", "--runs", "2", "--thresholds",
                "0.01,0.005,0.002", "--no-povray");
    }

    @Test
    void refusesThresholdsThatAreNotPositiveNumbers() {
        for (String bad : new String[] {"0.1,x", "0", "-0.01", "NaN", "Infinity", "0.1,,0.01"}) {
            assertThat(run("--thresholds", bad)).as(bad).isEqualTo(BenchCommand.INVALID);
            assertThat(err.toString(StandardCharsets.UTF_8)).contains("--thresholds");
        }
    }

    /** A bench scene file copied into {@code to} with its image size set to {@code width} x {@code height}. */
    private static void copyAtSize(String name, Path to, int width, int height) throws IOException {
        String json = Files.readString(BenchSceneFiles.dir().resolve(name));
        String resized = json.replaceFirst("\"image\": \\{[^}]*\\}",
                "\"image\": {\"width\": " + width + ", \"height\": " + height + "}");
        assertThat(resized).as(name + "'s image field").isNotEqualTo(json);
        Files.writeString(to.resolve(name), resized);
    }

    private static String imageSize(Path png) throws IOException {
        java.awt.image.BufferedImage image = javax.imageio.ImageIO.read(png.toFile());
        return image.getWidth() + "x" + image.getHeight();
    }

    @Test
    void aMissingPovRayLeavesItOffTheChart(@TempDir Path dir) {
        int code = run("--out", dir.toString(), "--width", "8", "--height", "6", "--runs", "1", "--reference-samples", "4",
                "--scenes", BenchSceneFiles.dir().toString(), "--povray", dir.resolve("no-povray").toString());
        assertThat(code).isEqualTo(BenchCommand.OK);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("no POV-Ray at");
    }

    @Test
    void triesEverySamplerTheEngineHas() {
        assertThat(EngineFeatures.SAMPLER_NAMES).contains("regular", "jittered");
        assertThat(EngineFeatures.sampler("jittered", 4)).isPresent();
        assertThat(EngineFeatures.sampler("no-such-sampler", 4)).isEmpty();
        for (String name : EngineFeatures.SAMPLER_NAMES) {
            if (EngineFeatures.sampler(name, 4).isPresent()) {
                assertThat(Sampler.of(name, 4).samplesPerPixel()).isEqualTo(4);
            }
        }
    }

    @Test
    void refusesBadArguments(@TempDir Path dir) {
        assertThat(run("--runs", "0")).isEqualTo(BenchCommand.INVALID);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("--runs needs a positive whole number");
        assertThat(run("--frobnicate")).isEqualTo(BenchCommand.INVALID);
        assertThat(run("--scenes", dir.toString(), "--out", dir.resolve("out").toString()))
                .isEqualTo(BenchCommand.INVALID);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("no scene files");
    }

    @Test
    void helpPrintsUsage() {
        assertThat(run("--help")).isEqualTo(BenchCommand.OK);
        assertThat(out.toString(StandardCharsets.UTF_8)).contains("usage: java -jar studio-bench.jar accuracy");
    }
}

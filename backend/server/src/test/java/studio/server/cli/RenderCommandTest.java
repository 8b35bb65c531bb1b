package studio.server.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The render command, run in-process on files in a temporary folder. */
class RenderCommandTest {

    private static final String TINY_SCENE = """
            {
              "name": "tiny",
              "image": { "width": 16, "height": 12, "format": "jpg" },
              "camera": { "position": [0, 1.5, 5], "lookAt": [0, 0.8, 0], "fov": 45 },
              "render": { "samples": 2, "maxDepth": 3 },
              "objects": [
                { "type": "sphere", "center": [0, 1, 0], "radius": 1, "material": { "type": "plastic", "color": "#cc3333" } },
                { "type": "sphere", "center": [1.5, 0.5, 0.5], "radius": 0.5, "material": { "type": "glass" } },
                { "type": "plane", "material": { "type": "chalk", "color": "#dddddd" } }
              ]
            }
            """;

    @TempDir
    Path dir;

    private Path scene;
    private final ByteArrayOutputStream outBytes = new ByteArrayOutputStream();
    private final ByteArrayOutputStream errBytes = new ByteArrayOutputStream();

    @BeforeEach
    void writeScene() throws IOException {
        scene = write("tiny.json", TINY_SCENE);
    }

    private Path write(String name, String content) throws IOException {
        return Files.writeString(dir.resolve(name), content, StandardCharsets.UTF_8);
    }

    private int run(String... args) {
        outBytes.reset();
        errBytes.reset();
        try (PrintStream out = new PrintStream(outBytes, true, StandardCharsets.UTF_8);
             PrintStream err = new PrintStream(errBytes, true, StandardCharsets.UTF_8)) {
            return RenderCommand.run(args, out, err);
        }
    }

    private String out() {
        return outBytes.toString(StandardCharsets.UTF_8);
    }

    private String err() {
        return errBytes.toString(StandardCharsets.UTF_8);
    }

    private List<String> errLines() {
        return err().lines().toList();
    }

    private static BufferedImage read(Path file) throws IOException {
        BufferedImage image = ImageIO.read(file.toFile());
        assertThat(image).as("an image readable from %s", file).isNotNull();
        return image;
    }

    /** The folder holds only the scene and these files: no temporary .part files left behind. */
    private void assertFolderHolds(String... names) throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            assertThat(files.map(p -> p.getFileName().toString()))
                    .containsExactlyInAnyOrder(Stream.concat(Stream.of("tiny.json"), Stream.of(names))
                            .toArray(String[]::new));
        }
    }

    // --- rendering -------------------------------------------------------------------------------

    @Test
    void rendersPngOfTheScenesSize() throws IOException {
        Path png = dir.resolve("out.png");
        assertThat(run(scene.toString(), "-o", png.toString())).as(err()).isEqualTo(RenderCommand.OK);
        byte[] bytes = Files.readAllBytes(png);
        assertThat(bytes).startsWith(0x89, 'P', 'N', 'G');
        BufferedImage image = read(png);
        assertThat(image.getWidth()).isEqualTo(16);
        assertThat(image.getHeight()).isEqualTo(12);
        assertThat(out()).startsWith("wrote " + png).contains("16x12").contains("at most 2");
        assertThat(err()).isEmpty();
        assertFolderHolds("out.png");
    }

    @Test
    void rendersWithASamplerNamedOnTheCommandLine() throws IOException {
        Path png = dir.resolve("sobol.png");
        assertThat(run(scene.toString(), "-o", png.toString(), "--sampler", "sobol", "--samples", "8"))
                .as(err()).isEqualTo(RenderCommand.OK);
        assertThat(out()).contains("at most 8");
        assertThat(RenderCommand.USAGE).contains("--sampler regular|random|jittered|multijittered|sobol");
    }

    @Test
    void reportsTheMeanSamplesPerPixelOfAnAdaptiveRender() throws IOException {
        Path adaptive = write("adaptive.json", TINY_SCENE.replace("\"render\": { \"samples\": 2,",
                "\"render\": { \"sampler\": \"multijittered\", \"samples\": 32, \"adaptive\": 0.05,"));
        assertThat(run(adaptive.toString(), "-o", dir.resolve("a.png").toString())).as(err())
                .isEqualTo(RenderCommand.OK);
        assertThat(out()).containsPattern("\\d+\\.\\d samples/pixel on average, at most 32");
    }

    @Test
    void adaptiveOptionTurnsOnAdaptiveSampling() throws IOException {
        assertThat(run(scene.toString(), "-o", dir.resolve("a.png").toString(), "--sampler", "sobol",
                "--samples", "32", "--adaptive", "0.05")).as(err()).isEqualTo(RenderCommand.OK);
        assertThat(out()).containsPattern("\\d+\\.\\d samples/pixel on average, at most 32");
    }

    @Test
    void adaptiveOptionOutOfRangeExitsWith2NamingTheField() {
        assertThat(run(scene.toString(), "-o", dir.resolve("a.png").toString(), "--adaptive", "2"))
                .isEqualTo(RenderCommand.INVALID);
        assertThat(errLines()).hasSize(1);
        assertThat(errLines().get(0)).startsWith("error:").contains("render.adaptive");
    }

    @Test
    void rendersJpgWhenTheOutputEndsInJpg() throws IOException {
        Path jpg = dir.resolve("out.jpg");
        assertThat(run(scene.toString(), "--output", jpg.toString(), "--quiet")).as(err()).isEqualTo(RenderCommand.OK);
        byte[] bytes = Files.readAllBytes(jpg);
        assertThat(bytes).startsWith(0xff, 0xd8, 0xff);
        BufferedImage image = read(jpg);
        assertThat(image.getWidth()).isEqualTo(16);
        assertThat(image.getHeight()).isEqualTo(12);
        assertThat(out()).as("--quiet prints nothing").isEmpty();
    }

    @Test
    void writesPngForPngOutputEvenIfSceneAsksForJpg() throws IOException {
        Path png = dir.resolve("out.PNG");
        assertThat(run(scene.toString(), "-o", png.toString(), "-q")).as(err()).isEqualTo(RenderCommand.OK);
        assertThat(Files.readAllBytes(png)).startsWith(0x89, 'P', 'N', 'G');
    }

    @Test
    void widthAndHeightOptionsOverrideTheScene() throws IOException {
        Path png = dir.resolve("big.png");
        assertThat(run(scene.toString(), "-o", png.toString(), "--width", "24", "--height", "10", "--samples", "1",
                "-q")).as(err()).isEqualTo(RenderCommand.OK);
        BufferedImage image = read(png);
        assertThat(image.getWidth()).isEqualTo(24);
        assertThat(image.getHeight()).isEqualTo(10);
    }

    @Test
    void overwritesAnExistingOutput() throws IOException {
        Path png = write("out.png", "not an image");
        assertThat(run(scene.toString(), "-o", png.toString(), "-q")).as(err()).isEqualTo(RenderCommand.OK);
        assertThat(read(png).getWidth()).isEqualTo(16);
        assertFolderHolds("out.png");
    }

    @Test
    void threadCountDoesNotChangeTheImage() throws IOException {
        Path one = dir.resolve("one.png");
        Path two = dir.resolve("two.png");
        assertThat(run(scene.toString(), "-o", one.toString(), "--threads", "1", "--width", "80", "--height", "70",
                "-q")).as(err()).isEqualTo(RenderCommand.OK);
        assertThat(run(scene.toString(), "-o", two.toString(), "--threads", "2", "--width", "80", "--height", "70",
                "-q")).as(err()).isEqualTo(RenderCommand.OK);
        assertThat(Files.readAllBytes(two)).isEqualTo(Files.readAllBytes(one));
    }

    @Test
    void helpPrintsUsage() {
        assertThat(run("--help")).isEqualTo(RenderCommand.OK);
        assertThat(out()).startsWith("usage:");
    }

    // --- errors ----------------------------------------------------------------------------------

    @Test
    void invalidSceneExitsWith2AndOneErrorLineNamingTheField() throws IOException {
        Path bad = write("bad.json", "{\"objects\": [{\"type\": \"sphere\", \"radius\": -1}]}");
        Path png = dir.resolve("bad.png");
        assertThat(run(bad.toString(), "-o", png.toString())).isEqualTo(RenderCommand.INVALID);
        assertThat(errLines()).hasSize(1);
        assertThat(errLines().get(0)).startsWith("error:").contains("objects[0].radius");
        assertThat(out()).isEmpty();
        assertThat(png).doesNotExist();
    }

    @Test
    void malformedSceneExitsWith2AndOneErrorLine() throws IOException {
        Path bad = write("bad.json", "{\"objects\": [\n{\"type\": \"sphere\",\n");
        assertThat(run(bad.toString(), "-o", dir.resolve("bad.png").toString())).isEqualTo(RenderCommand.INVALID);
        assertThat(errLines()).hasSize(1);
        assertThat(errLines().get(0)).startsWith("error:").contains("malformed JSON at line");
    }

    @Test
    void invalidOverrideExitsWith2NamingTheField() throws IOException {
        assertThat(run(scene.toString(), "-o", dir.resolve("x.png").toString(), "--sampler", "regular",
                "--samples", "3")).isEqualTo(RenderCommand.INVALID);
        assertThat(errLines()).hasSize(1);
        assertThat(errLines().get(0)).startsWith("error:").contains("render.samples");
    }

    @Test
    void unknownOptionExitsWith2AndPrintsUsage() {
        assertThat(run(scene.toString(), "--colour", "red")).isEqualTo(RenderCommand.INVALID);
        assertThat(errLines()).containsExactly("error: unknown option --colour", RenderCommand.USAGE);
    }

    @Test
    void nonNumericWidthExitsWith2() {
        assertThat(run(scene.toString(), "--width", "wide")).isEqualTo(RenderCommand.INVALID);
        assertThat(errLines().get(0)).startsWith("error:").contains("--width").contains("wide");
    }

    @Test
    void optionWithoutValueExitsWith2() {
        assertThat(run(scene.toString(), "-o")).isEqualTo(RenderCommand.INVALID);
        assertThat(errLines().get(0)).isEqualTo("error: -o needs a value");
    }

    @Test
    void noSceneExitsWith2AndPrintsUsage() {
        assertThat(run()).isEqualTo(RenderCommand.INVALID);
        assertThat(errLines()).containsExactly("error: no scene file given", RenderCommand.USAGE);
    }

    @Test
    void missingSceneFileExitsWith1() {
        Path missing = dir.resolve("nope.json");
        assertThat(run(missing.toString(), "-o", dir.resolve("x.png").toString())).isEqualTo(RenderCommand.IO_ERROR);
        assertThat(errLines()).containsExactly("error: no such scene file: " + missing);
    }

    @Test
    void gifOutputExitsWith2AndWritesNothing() throws IOException {
        Path gif = dir.resolve("out.gif");
        assertThat(run(scene.toString(), "-o", gif.toString())).isEqualTo(RenderCommand.INVALID);
        assertThat(errLines()).hasSize(1);
        assertThat(errLines().get(0)).startsWith("error:").contains(".png").contains(".jpg").contains("out.gif");
        assertFolderHolds();
    }

    @Test
    void unwritableOutputFolderExitsWith1() {
        Path png = dir.resolve("no-such-folder").resolve("out.png");
        assertThat(run(scene.toString(), "-o", png.toString(), "-q")).isEqualTo(RenderCommand.IO_ERROR);
        assertThat(errLines()).hasSize(1);
        assertThat(errLines().get(0)).startsWith("error: cannot write");
    }
}

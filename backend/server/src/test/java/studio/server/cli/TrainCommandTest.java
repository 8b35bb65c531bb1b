package studio.server.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code studio.jar train}: renders each file in turn, keeps nothing, and says what went wrong. */
class TrainCommandTest {

    private static final String SCENE = """
            {"version": 1, "image": {"width": 8, "height": 6}, "render": {"samples": 2},
             "camera": {"position": [0, 1, 4], "lookAt": [0, 0, 0], "fov": 50},
             "lights": [{"type": "point", "position": [2, 4, 3]}],
             "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": {"type": "%s"}}]}
            """;

    @TempDir
    Path dir;
    @TempDir
    Path temp;
    private final ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();

    /** Trains with the images in {@link #temp}, where the tests look for what is left. */
    private int train(String... args) {
        return TrainCommand.run(args, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8), temp);
    }

    private String scene(String name, String material) throws IOException {
        return Files.writeString(dir.resolve(name), SCENE.formatted(material)).toString();
    }

    private long leftInTemp() throws IOException {
        try (Stream<Path> files = Files.walk(temp)) {
            return files.filter(f -> !f.equals(temp)).count();
        }
    }

    @Test
    void rendersEveryFileAndLeavesNothingBehind() throws IOException {
        int code = train(scene("a.json", "chalk"), scene("b.json", "glass"));

        assertThat(code).as(err.toString()).isEqualTo(RenderCommand.OK);
        assertThat(out.toString()).isEmpty();
        assertThat(err.toString()).isEmpty();
        assertThat(leftInTemp()).as("images and their directory removed").isZero();
        try (Stream<Path> files = Files.list(dir)) {
            assertThat(files).as("nothing written beside the scenes").hasSize(2);
        }
    }

    @Test
    void stopsAtTheFirstSceneThatFailsWithItsCode() throws IOException {
        String good = scene("good.json", "chalk");
        Files.writeString(dir.resolve("bad.json"), "{\"version\": 1, \"objects\": [{\"type\": \"cone\"}]}");

        String missing = dir.resolve("missing.json").toString();
        assertThat(train(good, dir.resolve("bad.json").toString(), missing)).isEqualTo(RenderCommand.INVALID);
        assertThat(err.toString()).contains("bad.json", "objects[0].type").doesNotContain("missing.json");
        assertThat(leftInTemp()).isZero();

        err.reset();
        assertThat(train(missing)).isEqualTo(RenderCommand.IO_ERROR);
        assertThat(err.toString()).contains("missing.json");
    }

    @Test
    void wantsSceneFilesAndNothingElse() {
        assertThat(train()).isEqualTo(RenderCommand.INVALID);
        assertThat(err.toString()).contains(TrainCommand.USAGE);
        err.reset();
        assertThat(train("a.json", "-o", "x.png")).isEqualTo(RenderCommand.INVALID);
        assertThat(err.toString()).contains(TrainCommand.USAGE);
        assertThat(train("--help")).isEqualTo(RenderCommand.OK);
        assertThat(out.toString()).contains(TrainCommand.USAGE);
    }
}

package studio.server.bench;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import studio.server.scene.CompiledScene;
import studio.server.scene.ExampleSceneFiles;
import studio.server.scene.InvalidSceneException;
import studio.server.scene.SceneCompiler;

/** Every scene in scenes/bench is valid under the default limits, as the bench command reads it. */
class BenchScenesValidTest {

    private static final SceneCompiler COMPILER = ExampleSceneFiles.compiler();

    static Stream<Arguments> scenes() {
        return BenchSceneFiles.all().stream().map(p -> Arguments.of(BenchCommand.stem(p), p));
    }

    @Test
    void hasTheFourChartScenes() {
        assertThat(BenchSceneFiles.all().stream().map(BenchCommand::stem))
                .contains("edges", "stripes", "glass", "soft-shadows");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void compilesWithoutProblems(String name, Path file) throws IOException {
        try {
            CompiledScene compiled = COMPILER.compile(Files.readAllBytes(file));
            // no acceleration structure yet: render time grows with the object count
            assertThat(compiled.scene().objectCount()).as("objects in %s", name).isBetween(1, 40);
        } catch (InvalidSceneException e) {
            fail(name + " is not a valid scene: " + e.getMessage());
        }
    }
}

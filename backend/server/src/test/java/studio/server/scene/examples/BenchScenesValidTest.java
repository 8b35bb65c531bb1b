package studio.server.scene.examples;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.format.InvalidSceneException;

/**
 * Every scene in scenes/bench (the speed-against-accuracy benchmark's, in backend/bench) is valid
 * under the default limits.
 */
class BenchScenesValidTest {

    private static final SceneCompiler COMPILER = ExampleSceneFiles.compiler();

    static Stream<Arguments> scenes() throws IOException {
        return benchScenes().stream().map(p -> Arguments.of(ExampleSceneFiles.stem(p), p));
    }

    private static List<Path> benchScenes() throws IOException {
        try (Stream<Path> files = Files.list(ExampleSceneFiles.dir().resolve("bench"))) {
            return files.filter(p -> p.getFileName().toString().endsWith(".json")).sorted().toList();
        }
    }

    @Test
    void hasTheFourChartScenes() throws IOException {
        assertThat(benchScenes().stream().map(ExampleSceneFiles::stem))
                .contains("edges", "stripes", "glass", "soft-shadows");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void compilesWithoutProblems(String name, Path file) throws IOException {
        try {
            CompiledScene compiled = COMPILER.compile(CompileRequest.of(Files.readAllBytes(file)));
            // no acceleration structure yet: render time grows with the object count
            assertThat(compiled.scene().objectCount()).as("objects in %s", name).isBetween(1, 40);
        } catch (InvalidSceneException e) {
            fail(name + " is not a valid scene: " + e.getMessage());
        }
    }
}

package studio.server.scene.examples;

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

import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.format.InvalidSceneException;

/** Every example in scenes/ is a valid scene under the default limits, as the CLI and the API read it. */
class ExampleScenesValidTest {

    private static final SceneCompiler COMPILER = ExampleSceneFiles.compiler();

    static Stream<Arguments> scenes() {
        return ExampleSceneFiles.all().stream().map(p -> Arguments.of(ExampleSceneFiles.stem(p), p));
    }

    @Test
    void thereAreExampleScenes() {
        assertThat(ExampleSceneFiles.all()).isNotEmpty();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void compilesWithoutProblems(String name, Path file) throws IOException {
        byte[] json = Files.readAllBytes(file);
        try {
            CompiledScene compiled = COMPILER.compile(CompileRequest.of(json));
            assertThat(compiled.scene().objectCount()).as("objects in %s", name).isPositive();
        } catch (InvalidSceneException e) {
            fail(name + " is not a valid scene: " + e.getMessage());
        }
    }
}

package studio.server.scene.examples;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import jakarta.validation.Validation;
import jakarta.validation.ValidatorFactory;

import studio.server.scene.compiling.MeshFiles;
import studio.server.scene.compiling.SceneCompiler;

/** The scenes/ folder of the repository, for tests. */
public final class ExampleSceneFiles {

    /** One validator factory for every test that compiles scenes (building one is not cheap). */
    private static final ValidatorFactory VALIDATION = Validation.buildDefaultValidatorFactory();

    private ExampleSceneFiles() {
    }

    public static Path dir() {
        String configured = System.getProperty("studio.scenesDir");
        Path dir = configured != null ? Path.of(configured) : Path.of("../../scenes");
        if (!Files.isDirectory(dir)) {
            throw new IllegalStateException("cannot find the scenes folder at " + dir.toAbsolutePath());
        }
        return dir.normalize();
    }

    public static List<Path> all() {
        try (Stream<Path> files = Files.list(dir())) {
            return files.filter(p -> p.getFileName().toString().endsWith(".json")).sorted().toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    public static String stem(Path file) {
        String name = file.getFileName().toString();
        return name.substring(0, name.length() - ".json".length());
    }

    /** A compiler with the default limits, as the CLI builds it, reading meshes from the scenes folder. */
    public static SceneCompiler compiler() {
        return SceneCompiler.standalone(VALIDATION::getValidator, MeshFiles.in(dir()));
    }
}

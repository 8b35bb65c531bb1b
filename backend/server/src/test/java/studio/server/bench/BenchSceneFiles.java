package studio.server.bench;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/** The scenes/bench folder of the repository, for tests (as ExampleSceneFiles is for scenes/). */
final class BenchSceneFiles {

    private BenchSceneFiles() {
    }

    static Path dir() {
        String configured = System.getProperty("studio.benchScenesDir");
        Path dir = configured != null ? Path.of(configured) : Path.of("../../scenes/bench");
        if (!Files.isDirectory(dir)) {
            throw new IllegalStateException("cannot find the bench scenes folder at " + dir.toAbsolutePath());
        }
        return dir.normalize();
    }

    static List<Path> all() {
        try {
            return BenchCommand.sceneFiles(dir());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}

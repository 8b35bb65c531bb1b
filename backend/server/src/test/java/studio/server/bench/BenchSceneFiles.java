package studio.server.bench;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import studio.server.scene.ExampleSceneFiles;

/** The scenes/bench folder of the repository, for tests (as ExampleSceneFiles is for scenes/). */
final class BenchSceneFiles {

    private BenchSceneFiles() {
    }

    static Path dir() {
        Path dir = ExampleSceneFiles.dir().resolve("bench");
        if (!Files.isDirectory(dir)) {
            throw new IllegalStateException("cannot find the bench scenes folder at " + dir.toAbsolutePath());
        }
        return dir;
    }

    static List<Path> all() {
        try {
            return BenchCommand.sceneFiles(dir());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}

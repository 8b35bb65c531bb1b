package studio.bench.accuracy;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/** The scenes/bench folder of the repository, for tests: found from the working directory up. */
final class BenchSceneFiles {

    private BenchSceneFiles() {
    }

    static Path dir() {
        for (Path at = Path.of("").toAbsolutePath(); at != null; at = at.getParent()) {
            Path dir = at.resolve("scenes").resolve("bench");
            if (Files.isDirectory(dir)) {
                return dir;
            }
        }
        throw new IllegalStateException("cannot find scenes/bench above " + Path.of("").toAbsolutePath());
    }

    static List<Path> all() {
        try {
            return BenchCommand.sceneFiles(dir());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}

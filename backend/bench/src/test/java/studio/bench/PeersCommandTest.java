package studio.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The peers command's scenes: the benchmark's names, and scene files for scenes it was not tuned on. */
class PeersCommandTest {

    @TempDir
    Path dir;

    @Test
    void aSceneFileIsNamedByItsFileAndMixesWithTheBenchmarksNames() throws IOException {
        Path file = Files.writeString(dir.resolve("held-out-glass.json"), "{}");
        PeersCommand.Options o = PeersCommand.Options.parse(new String[] {"--scenes", "still-life," + file});
        assertEquals(List.of("still-life", file.toString()), o.scenes);
        assertTrue(PeersCommand.isSceneFile(file.toString()));
        assertFalse(PeersCommand.isSceneFile("still-life"));
        assertEquals("held-out-glass", PeersCommand.sceneName(file.toString()));
        assertEquals("glass", PeersCommand.sceneName("glass"));
    }

    @Test
    void aMissingSceneFileOrAnUnknownNameIsRefusedBeforeAnythingRuns() {
        IllegalArgumentException missing = assertThrows(IllegalArgumentException.class,
                () -> PeersCommand.Options.parse(new String[] {"--scenes", dir.resolve("nowhere.json").toString()}));
        assertTrue(missing.getMessage().contains("nowhere.json"), missing.getMessage());
        IllegalArgumentException unknown = assertThrows(IllegalArgumentException.class,
                () -> PeersCommand.Options.parse(new String[] {"--scenes", "teapot"}));
        assertTrue(unknown.getMessage().contains("or a scene file"), unknown.getMessage());
    }

    @Test
    void twoScenesWithOneNameAreRefusedSinceTheyWouldShareAFolderAndARow() throws IOException {
        Path file = Files.writeString(dir.resolve("glass.json"), "{}");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> PeersCommand.Options.parse(new String[] {"--scenes", "glass," + file}));
        assertTrue(e.getMessage().contains("two scenes named 'glass'"), e.getMessage());
    }
}

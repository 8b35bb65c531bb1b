package studio.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;

/** How ours is started: the jar asked for runs, through the launcher or without it. */
class RenderersTest {

    private static final Path JAR = Path.of("/tmp/elsewhere/studio.jar");

    private static Renderers renderers(Path launcher) {
        return new Renderers(Path.of("java"), JAR, Path.of("povray"), Path.of("sunflow.jar"), Path.of("classes"),
                800, 600, 2, launcher);
    }

    @Test
    void theLauncherRunsTheJarAskedForNotItsDefault() {
        List<String> cmd = renderers(Path.of("bin/studio")).ours(Path.of("s.json"), Path.of("o.png"), 16);
        assertEquals(List.of("env", "STUDIO_JAR=" + JAR, "bin/studio", "render", "s.json", "-o", "o.png"), cmd.subList(0, 7));
    }

    @Test
    void withoutTheLauncherTheJarRunsDirectly() {
        List<String> cmd = renderers(null).ours(Path.of("s.json"), Path.of("o.png"), 1);
        assertEquals(List.of("java", "-jar", JAR.toString(), "render"), cmd.subList(0, 4));
        assertEquals(List.of("--sampler", "regular"), cmd.subList(cmd.indexOf("--sampler"), cmd.indexOf("--sampler") + 2));
    }

    @Test
    void theReportSaysWhichWayOursRan() {
        assertEquals("through bin/studio", MachineSetup.ours(renderers(Path.of("bin/studio"))));
        assertEquals("as java -jar, without bin/studio's start-up cache", MachineSetup.ours(renderers(null)));
    }
}

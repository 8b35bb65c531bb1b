package studio.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import javax.imageio.ImageIO;

import jakarta.validation.Validation;
import jakarta.validation.ValidatorFactory;

import studio.engine.image.ImageEncoder;
import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.MeshFiles;
import studio.server.scene.compiling.SceneMapper;
import studio.server.scene.format.SceneDto;
import studio.server.scene.format.SceneLimits;
import studio.server.scene.reading.SceneReader;

/** Small renders of one scene file by ours (in this JVM), POV-Ray (a process) and Sunflow (in this JVM). */
final class TestRenders {

    static final Path POVRAY = Path.of("/usr/bin/povray");

    private TestRenders() {
    }

    static SceneDto read(String json) {
        try (ValidatorFactory validation = Validation.buildDefaultValidatorFactory()) {
            return new SceneReader(validation.getValidator()).read(json.getBytes(StandardCharsets.UTF_8));
        }
    }

    /** Ours at one sample per pixel through the pixel centres, whatever the scene's render settings. */
    static BufferedImage ours(String json, int width, int height) {
        return ours(json, width, height, MeshFiles.none());
    }

    /** As {@link #ours(String, int, int)}, mesh files read from {@code meshFiles} (as the CLI: beside the scene). */
    static BufferedImage ours(String json, int width, int height, MeshFiles meshFiles) {
        try (ValidatorFactory validation = Validation.buildDefaultValidatorFactory()) {
            SceneDto dto = new SceneReader(validation.getValidator()).read(json.getBytes(StandardCharsets.UTF_8),
                    Map.of("image.width", width, "image.height", height, "render.samples", 1,
                            "render.sampler", "regular"));
            CompiledScene compiled = new SceneMapper(SceneLimits.DEFAULTS).map(dto, 1, meshFiles);
            return ImageEncoder.toImage(Renderer.render(RenderRequest.of(compiled.scene(), compiled.settings())).film());
        }
    }

    /** POV-Ray without anti-aliasing (one ray through each pixel centre); skips the test without POV-Ray. */
    static BufferedImage povray(String sdl, int width, int height, Path dir) throws IOException, InterruptedException {
        assumeTrue(Files.isExecutable(POVRAY), "POV-Ray is not installed at " + POVRAY);
        Path pov = Files.writeString(dir.resolve("scene.pov"), sdl);
        Path png = dir.resolve("povray.png");
        Process p = new ProcessBuilder(POVRAY.toString(), "+I" + pov, "+O" + png, "+W" + width, "+H" + height,
                "+WT1", "-D", "-V", "+FN", "-P", "-A").redirectErrorStream(true)
                .redirectOutput(dir.resolve("povray.log").toFile()).start();
        assertEquals(true, p.waitFor(120, TimeUnit.SECONDS), "POV-Ray took too long");
        assertEquals(0, p.exitValue(), () -> "POV-Ray failed: " + log(dir.resolve("povray.log")));
        return ImageIO.read(png.toFile());
    }

    /** Sunflow at one sample per pixel, through {@link SunflowRender} in this JVM. */
    static BufferedImage sunflow(SunflowScript script, Path dir) throws IOException {
        Path sfs = dir.resolve("scene.sfs");
        script.write(sfs);
        Path png = dir.resolve("sunflow.png");
        assertEquals(0, SunflowRender.render(sfs, png), "Sunflow reported errors");
        return ImageIO.read(png.toFile());
    }

    private static String log(Path file) {
        try {
            List<String> lines = Files.readAllLines(file);
            return String.join("\n", lines.subList(Math.max(0, lines.size() - 10), lines.size()));
        } catch (IOException e) {
            return e.toString();
        }
    }
}

package studio.server.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import tools.jackson.databind.node.ObjectNode;

import studio.server.scene.gltf.TestGltf;

/** The command line renders a glTF model named by its file beside the scene, and names a broken one. */
class GltfCommandLineTest {

    /** The red glowing triangle (0,0,0), (2,0,0), (0,2,0) moved by its object to (-1,-1,0): the lower left half of [-1,1]^2. */
    private static final String SCENE = """
            {"image": {"width": 33, "height": 33, "format": "png"}, "render": {"samples": 1},
             "camera": {"position": [0, 0, 5], "lookAt": [0, 0, 0], "fov": 60},
             "objects": [{"type": "gltf", "file": "models/triangle.glb", "position": [-1, -1, 0], "scale": 2}]}
            """;

    @TempDir
    Path dir;

    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private int render(Path scene, Path image) {
        try (PrintStream out = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
             PrintStream errors = new PrintStream(err, true, StandardCharsets.UTF_8)) {
            return RenderCommand.run(new String[] {scene.toString(), "-o", image.toString(), "-q"}, out, errors);
        }
    }

    private static byte[] redTriangle() {
        ObjectNode gltf = TestGltf.triangle();
        ((ObjectNode) gltf.get("materials").get(0)).set("emissiveFactor", TestGltf.JSON.readTree("[1, 0, 0]"));
        return TestGltf.glb(gltf, TestGltf.triangleBuffer());
    }

    @Test
    void rendersAGlbBesideTheScene() throws IOException {
        Files.createDirectories(dir.resolve("models"));
        Files.write(dir.resolve("models/triangle.glb"), redTriangle());
        Path scene = Files.writeString(dir.resolve("scene.json"), SCENE);
        Path png = dir.resolve("scene.png");

        assertThat(render(scene, png)).as(err.toString(StandardCharsets.UTF_8)).isEqualTo(RenderCommand.OK);
        BufferedImage image = ImageIO.read(png.toFile());
        assertThat(image.getRGB(13, 19) & 0xffffff).isEqualTo(0xff0000); // (-0.5, -0.5, 0)
        assertThat(image.getRGB(19, 13) & 0xffffff).isNotEqualTo(0xff0000); // (0.5, 0.5, 0)
    }

    @Test
    void aTruncatedGlbExitsWith2NamingTheField() throws IOException {
        Files.createDirectories(dir.resolve("models"));
        byte[] glb = redTriangle();
        Files.write(dir.resolve("models/triangle.glb"), Arrays.copyOf(glb, glb.length - 8));
        Path scene = Files.writeString(dir.resolve("scene.json"), SCENE);
        Path png = dir.resolve("scene.png");

        assertThat(render(scene, png)).isEqualTo(RenderCommand.INVALID);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("objects[0].file").contains("truncated");
        assertThat(png).doesNotExist();
    }
}

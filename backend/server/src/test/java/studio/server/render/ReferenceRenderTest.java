package studio.server.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import studio.engine.image.ImageEncoder;
import studio.engine.render.RenderResult;
import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.examples.ExampleSceneFiles;

/**
 * Every scene in scenes/ rendered small and compared with its checked-in reference in
 * scenes/expected/: PSNR at least {@value #MIN_PSNR} dB over the 8-bit sRGB channels and at most
 * {@value #MAX_OUTLIERS} of pixels more than 24 code values off. The translated and scaled copies
 * of the still life are compared with the still life's own reference.
 *
 * <p>References change only deliberately: {@code mvn test -Dstudio.updateReferences=true} rewrites
 * them (then review the images and say why in the commit). On failure the actual image and a
 * difference image go to target/reference-renders/.
 */
class ReferenceRenderTest {

    static final double MIN_PSNR = 40;
    static final double MAX_OUTLIERS = 0.002;
    static final int WIDTH = 160;
    static final int MAX_SAMPLES = 16;

    /** Copies that must look exactly like another scene. */
    static final Map<String, String> SAME_AS = Map.of(
            "still-life-translated", "still-life",
            "still-life-scaled", "still-life",
            "still-life-far-small", "still-life");

    static Stream<Arguments> scenes() {
        return ExampleSceneFiles.all().stream().map(p -> Arguments.of(ExampleSceneFiles.stem(p), p));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void matchesReference(String name, Path file) throws IOException {
        BufferedImage actual = renderSmall(file);
        String referenceName = SAME_AS.getOrDefault(name, name);
        Path reference = ExampleSceneFiles.dir().resolve("expected").resolve(referenceName + ".png");
        if (Boolean.getBoolean("studio.updateReferences")) {
            if (!SAME_AS.containsKey(name)) { // copies are never references of their own
                Files.createDirectories(reference.getParent());
                ImageIO.write(actual, "png", reference.toFile());
            }
            return;
        }
        assertTrue(Files.exists(reference), "no reference image " + reference
                + "; create it with -Dstudio.updateReferences=true and review it");
        BufferedImage expected = ImageIO.read(reference.toFile());
        ImageComparison comparison = ImageComparison.of(expected, actual);
        System.out.printf("reference %-22s vs %-12s PSNR %6.1f dB, outliers %.3f%%%n", name, referenceName,
                comparison.psnr(), 100 * comparison.outlierFraction());
        boolean ok = comparison.psnr() >= MIN_PSNR && comparison.outlierFraction() <= MAX_OUTLIERS;
        if (!ok) {
            Path out = Path.of("target", "reference-renders");
            Files.createDirectories(out);
            ImageIO.write(actual, "png", out.resolve(name + "-actual.png").toFile());
            ImageIO.write(comparison.diff(), "png", out.resolve(name + "-diff.png").toFile());
        }
        assertTrue(ok, String.format("%s differs from %s.png: PSNR %.1f dB (min %.0f), outliers %.3f%% (max %.1f%%); "
                        + "see target/reference-renders/", name, referenceName, comparison.psnr(), MIN_PSNR,
                100 * comparison.outlierFraction(), 100 * MAX_OUTLIERS));
    }

    /** The scene at WIDTH pixels wide (same aspect), at most MAX_SAMPLES samples per pixel. */
    static BufferedImage renderSmall(Path file) throws IOException {
        byte[] json = Files.readAllBytes(file);
        SceneCompiler compiler = ExampleSceneFiles.compiler();
        CompiledScene full = compiler.compile(CompileRequest.of(json));
        int height = Math.max(1, Math.round((float) WIDTH * full.settings().height() / full.settings().width()));
        int samples = full.settings().sampler().samplesPerPixel();
        CompiledScene small = compiler.compile(CompileRequest.of(json).overriding(Map.of("image.width", WIDTH, "image.height", height,
                "render.samples", samples > MAX_SAMPLES ? MAX_SAMPLES : samples)));
        RenderResult result = Renderer.render(RenderRequest.of(small.scene(), small.settings()));
        assertEquals(0, result.nonFiniteSamples(), "NaN or infinite samples in " + file);
        return ImageEncoder.toImage(result.film());
    }

}

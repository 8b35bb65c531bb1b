package studio.server.preview;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.Locale;
import java.util.Map;
import java.util.function.Function;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;

import studio.engine.scene.Scene;
import studio.server.render.RenderBudget;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.reading.LazyValidation;
import studio.server.system.MemoryBudget;
import tools.jackson.databind.json.JsonMapper;

/**
 * A revision that moves a mesh is compiled without the light buffers only its final pass pays
 * for; the live view's finer passes get them ({@link PreviewRenderer#lit}), their memory asked of
 * the pass's reservation, and the view keeps them for the next revision. Buffers change no pixel.
 */
class MovedMeshLightBuffersTest {

    /** 64 x 48 at 16 samples pays for the knot's 960 triangles' buffers (8 samples a triangle), one sample does not. */
    private static final int WIDTH = 64, HEIGHT = 48;
    private static final LazyValidation VALIDATION = new LazyValidation();
    private static final SceneCompiler COMPILER = SceneCompiler.standalone(VALIDATION);
    private static final Function<byte[], CompiledScene> READ = json -> COMPILER.compile(
            CompileRequest.of(json).overriding(Map.of("image.width", WIDTH, "image.height", HEIGHT)).onThreads(1));
    private static final PreviewRenderer RENDERER = new PreviewRenderer(COMPILER, RenderBudget.unlimited(), 1,
            new PreviewProperties(16, 2048, 2048, Duration.ofMinutes(10)), JsonMapper.builder().build());

    @AfterAll
    static void close() {
        VALIDATION.close();
    }

    private static String scene() {
        String knot = PatchedView.knotObj();
        return "{\"render\": {\"samples\": 16, \"maxDepth\": 4},"
                + "\"camera\": {\"position\": [0, 3, 9], \"lookAt\": [0, 1, 0], \"fov\": 45},"
                + "\"lights\": [{\"type\": \"point\", \"position\": [4, 7, 5]}, {\"type\": \"point\", \"position\": [-5, 4, 3],"
                + " \"intensity\": 0.4}],"
                + "\"objects\": [{\"type\": \"mesh\", \"obj\": \"" + knot + "\", \"position\": [0, 1.2, 0],"
                + " \"scale\": 0.6, \"material\": {\"type\": \"plastic\", \"color\": \"#c0a060\"}},"
                + "{\"type\": \"sphere\", \"center\": [1.5, 0.5, 1], \"radius\": 0.5, \"material\": {\"type\": \"mirror\"}},"
                + "{\"type\": \"plane\"}]}";
    }

    private static String move(int object, String field, double x, double y, double z) {
        return String.format(Locale.ROOT, "[{\"op\": \"replace\", \"path\": \"/objects/%d/%s\", \"value\": [%s, %s, %s]}]",
                object, field, x, y, z);
    }

    private static double[] pixels(Scene scene) {
        return PatchedView.pixels(scene, WIDTH, HEIGHT, 2);
    }

    @Test
    void aMovedMeshGetsItsBuffersForTheFinerPassesFromThePassMemoryAndRendersTheSame() {
        MemoryBudget budget = new MemoryBudget(1L << 30);
        try (PatchedView view = new PatchedView(scene(), WIDTH, HEIGHT, READ);
             MemoryBudget.Reservation pass = budget.tryReserve(1 << 20)) {
            assertThat(RENDERER.lit(view.first, pass)).as("a scene read whole has its buffers").isSameAs(view.first);
            assertThat(pass.bytes()).isEqualTo(1 << 20);

            CompiledScene moved = view.patch(move(0, "position", 0.4, 1.3, -0.2)).compiled();
            CompiledScene lit = RENDERER.lit(moved, pass);
            assertThat(lit).isNotSameAs(moved);
            assertThat(pass.bytes()).as("the buffers' memory, asked of the pass's").isGreaterThan(1 << 20);
            assertThat(RENDERER.lit(lit, pass)).isSameAs(lit);
            double[] whole = pixels(view.readInFull().scene());
            assertThat(pixels(moved.scene())).isEqualTo(whole);
            assertThat(pixels(lit.scene())).isEqualTo(whole);

            view.reuse.lit(moved, lit);
            long held = pass.bytes();
            CompiledScene next = view.patch(move(1, "center", 1.2, 0.5, 1.4)).compiled();
            assertThat(RENDERER.lit(next, pass)).as("the mesh kept its buffers from the revision before").isSameAs(next);
            assertThat(pass.bytes()).isEqualTo(held);
            assertThat(pixels(next.scene())).isEqualTo(pixels(view.readInFull().scene()));
        }
    }

    @Test
    void withoutMemoryForThemTheMovedMeshRendersWithoutBuffers() {
        MemoryBudget budget = new MemoryBudget(2L << 20);
        try (PatchedView view = new PatchedView(scene(), WIDTH, HEIGHT, READ);
             MemoryBudget.Reservation pass = budget.tryReserve(2L << 20)) {
            CompiledScene moved = view.patch(move(0, "position", -0.3, 1.1, 0.2)).compiled();
            CompiledScene lit = RENDERER.lit(moved, pass);
            assertThat(pass.bytes()).isEqualTo(2L << 20);
            assertThat(pixels(lit.scene())).isEqualTo(pixels(view.readInFull().scene()));
        }
    }
}

package studio.server.preview;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.function.Function;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;

import studio.engine.scene.Scene;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.reading.LazyValidation;

/**
 * A patched revision of a large scene refits the last revision's tree ({@link Scene#reusing}) and
 * renders, to the bit, what the patched scene sent whole renders: after one sphere of 10,000 moved,
 * after a mesh moved beside them, and after many patches, when the tree and its light buffers have
 * been built again on the way.
 */
class PatchedTreeTest {

    private static final int WIDTH = 64, HEIGHT = 48;
    private static final LazyValidation VALIDATION = new LazyValidation();
    private static final SceneCompiler COMPILER = SceneCompiler.standalone(VALIDATION);
    private static final Function<byte[], CompiledScene> READ = json -> COMPILER.compile(
            CompileRequest.of(json).overriding(Map.of("image.width", WIDTH, "image.height", HEIGHT)).onThreads(1));

    @AfterAll
    static void close() {
        VALIDATION.close();
    }

    /** A mirror ball in front, a knot mesh, {@code n} small spheres behind them, a floor, two lights. */
    private static String scene(int n) {
        String knot = PatchedView.knotObj();
        Random random = new Random(45);
        StringBuilder json = new StringBuilder("{\"render\": {\"samples\": 1, \"maxDepth\": 4},"
                + "\"camera\": {\"position\": [0, 3, 9], \"lookAt\": [0, 1, 0], \"fov\": 45},"
                + "\"lights\": [{\"type\": \"point\", \"position\": [4, 7, 5]}, {\"type\": \"point\", \"position\": [-5, 4, 3],"
                + " \"intensity\": 0.4}],"
                + "\"objects\": [{\"type\": \"sphere\", \"center\": [0, 0.8, 2.5], \"radius\": 0.6, \"material\": {\"type\": \"mirror\"}},"
                + "{\"type\": \"mesh\", \"obj\": \"" + knot + "\", \"position\": [1.5, 1, 1],"
                + " \"scale\": 0.3, \"material\": {\"type\": \"metal\", \"color\": \"#c0a060\"}}");
        String[] materials = {"chalk", "plastic", "metal"};
        for (int i = 2; i < n; i++) {
            json.append(String.format(Locale.ROOT, ",{\"type\": \"sphere\", \"center\": [%.3f, %.3f, %.3f], \"radius\": 0.07,"
                            + " \"material\": {\"type\": \"%s\", \"color\": \"#%06x\"}}", -4 + 8 * random.nextDouble(),
                    0.07 + 3 * random.nextDouble(), -4 + 6 * random.nextDouble(), materials[i % 3], random.nextInt(1 << 24)));
        }
        return json.append(",{\"type\": \"plane\"}]}").toString();
    }

    /** A view sent a whole scene of {@code n} objects ({@link #scene}), then patches. */
    private static PatchedView view(int n) {
        return new PatchedView(scene(n), WIDTH, HEIGHT, READ);
    }

    private static double[] pixels(Scene scene) {
        return PatchedView.pixels(scene, WIDTH, HEIGHT, 1);
    }

    private static String move(int object, String field, double x, double y, double z) {
        return String.format(Locale.ROOT, "{\"op\": \"replace\", \"path\": \"/objects/%d/%s\", \"value\": [%s, %s, %s]}",
                object, field, x, y, z);
    }

    @Test
    void movingOneOfTenThousandSpheresRendersWhatTheWholeSceneRenders() {
        try (PatchedView view = view(10_000)) {
            Scene moved = view.patch("[" + move(0, "center", 0.7, 0.9, 2.2) + "]").compiled().scene();
            assertThat(view.assembled()).isOne();
            assertThat(pixels(moved)).isEqualTo(pixels(view.readInFull().scene()));
            Scene again = view.patch("[" + move(0, "center", -0.6, 0.8, 2.6) + "]").compiled().scene();
            assertThat(pixels(again)).isEqualTo(pixels(view.readInFull().scene())).isNotEqualTo(pixels(moved));
        }
    }

    @Test
    void aMovedMeshAmongTheSpheresRendersWhatTheWholeSceneRenders() {
        try (PatchedView view = view(3_000)) {
            Scene moved = view.patch("[" + move(1, "position", 0.5, 1.2, 1.5) + "," + move(0, "center", -1, 0.7, 2.4) + "]")
                    .compiled().scene();
            assertThat(view.assembled()).isOne();
            assertThat(pixels(moved)).isEqualTo(pixels(view.readInFull().scene()));
        }
    }

    @Test
    void manyPatchesRebuildOnTheWayAndStillRenderWhatTheWholeSceneRenders() {
        try (PatchedView view = view(3_000)) {
            // different spheres each time (more than the light buffers keep beside them), some thrown far
            // enough that the refitted tree would cost too much and is built again
            for (int i = 0; i < 24; i++) {
                int object = 2 + 37 * i;
                view.patch("[" + move(object, "center", i % 3 == 0 ? 30 + i : -3 + 0.25 * i, 0.5 + 0.1 * i, 1 - 0.2 * i) + "]");
            }
            Scene last = view.patch("[" + move(0, "center", 0.4, 0.8, 2) + "]").compiled().scene();
            assertThat(view.assembled()).isEqualTo(25);
            assertThat(pixels(last)).isEqualTo(pixels(view.readInFull().scene()));
        }
    }
}

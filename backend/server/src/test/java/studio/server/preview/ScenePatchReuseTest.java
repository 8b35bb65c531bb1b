package studio.server.preview;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Map;
import java.util.function.Function;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;

import studio.engine.geometry.TriangleMesh;
import studio.engine.render.Film;
import studio.engine.render.RenderSettings;
import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.engine.sampler.Sampler;
import studio.engine.scene.Scene;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.reading.LazyValidation;

/**
 * A patched revision reads only the objects the patch's paths name, keeps every other object (and a
 * moved mesh's tree), and is the scene reading the patched JSON in full gives, to the pixel.
 */
class ScenePatchReuseTest {

    private static final LazyValidation VALIDATION = new LazyValidation();
    private static final SceneCompiler COMPILER = SceneCompiler.standalone(VALIDATION);
    private static final Function<byte[], CompiledScene> READ =
            json -> COMPILER.compile(CompileRequest.of(json).overriding(Map.of("image.width", 48, "image.height", 36)).onThreads(1));

    @AfterAll
    static void close() {
        VALIDATION.close();
    }

    private static String scene() {
        String knot = PatchedView.knotObj();
        StringBuilder spheres = new StringBuilder();
        for (int i = 0; i < 40; i++) {
            spheres.append(",{\"type\": \"sphere\", \"center\": [%s, %s, -1], \"radius\": 0.1, \"material\": {\"type\": \"plastic\"}}"
                    .formatted(-2 + 0.1 * i, 0.2 + 0.05 * (i % 7)));
        }
        return """
                {"image": {"width": 320, "height": 240}, "render": {"samples": 4, "sampler": "jittered"},
                 "camera": {"position": [0, 2, 6], "lookAt": [0, 0.5, 0]},
                 "lights": [{"type": "point", "position": [3, 5, 4]}],
                 "objects": [{"type": "plane"},
                             {"type": "mesh", "obj": "%s", "position": [0, 0.8, 0], "scale": 0.4,
                              "material": {"type": "metal", "color": "#c0a060"}}%s]}
                """.formatted(knot, spheres);
    }

    private static PatchedView view() {
        return new PatchedView(scene(), 48, 36, READ);
    }

    private static double[] pixels(Scene scene) {
        Film film = Renderer.render(RenderRequest.of(scene, new RenderSettings(48, 36, Sampler.of("jittered", 4), 4, 1, 7L,
                RenderSettings.DEFAULT_MIN_PATH_WEIGHT, 0))).film();
        double[] all = new double[48 * 36 * 3];
        for (int y = 0, k = 0; y < 36; y++) {
            for (int x = 0; x < 48; x++) {
                for (int c = 0; c < 3; c++) {
                    all[k++] = film.get(x, y, c);
                }
            }
        }
        return all;
    }

    @Test
    void aPatchedObjectIsReadAloneAndTheOthersKept() {
        try (PatchedView view = view()) {
            SceneReuse.Revision moved = view.patch("[{\"op\": \"replace\", \"path\": \"/objects/5/center\", \"value\": [0.3, 1, 0]}]");
            assertThat(view.assembled()).isOne();
            assertThat(moved.origins()[5]).isEqualTo(-1);
            assertThat(moved.origins()[6]).isEqualTo(6);
            Scene scene = moved.compiled().scene();
            assertThat(scene.shape(6)).isSameAs(view.first.scene().shape(6));
            assertThat(scene.shape(1)).isSameAs(view.first.scene().shape(1));
            assertThat(pixels(scene)).isEqualTo(pixels(view.readInFull().scene())).isNotEqualTo(pixels(view.first.scene()));
        }
    }

    @Test
    void aPatchThatChangesNothingIsTheLastScene() {
        try (PatchedView view = view()) {
            SceneReuse.Revision same = view.patch("[{\"op\": \"test\", \"path\": \"/objects/1/scale\", \"value\": 0.4}]");
            assertThat(same.compiled()).isSameAs(view.first);
            assertThat(view.patch("[]").compiled()).isSameAs(view.first);
        }
    }

    @Test
    void aMovedMeshKeepsItsTree() {
        try (PatchedView view = view()) {
            SceneReuse.Revision moved = view.patch("[{\"op\": \"replace\", \"path\": \"/objects/1/position\", \"value\": [0.3, 0.8, 0]},"
                    + "{\"op\": \"replace\", \"path\": \"/objects/1/material/color\", \"value\": \"#3060c0\"}]");
            assertThat(view.assembled()).isOne();
            TriangleMesh mesh = (TriangleMesh) moved.compiled().scene().shape(1);
            assertThat(mesh.buildNanos()).as("the kept mesh moved, its tree not built again").isZero();
            assertThat(pixels(moved.compiled().scene())).isEqualTo(pixels(view.readInFull().scene()));

            view.patch("[{\"op\": \"replace\", \"path\": \"/objects/1/scale\", \"value\": 0.5}]");
            assertThat(view.assembled()).as("a scaled mesh is read in full").isOne();
        }
    }

    @Test
    void aChangedCameraOrLightKeepsEveryObject() {
        try (PatchedView view = view()) {
            SceneReuse.Revision turned = view.patch("[{\"op\": \"replace\", \"path\": \"/camera/position\", \"value\": [1, 2, 6]},"
                    + "{\"op\": \"add\", \"path\": \"/lights/-\", \"value\": {\"type\": \"point\", \"position\": [-3, 3, 3]}}]");
            assertThat(view.assembled()).isOne();
            Scene scene = turned.compiled().scene();
            assertThat(scene.shape(7)).isSameAs(view.first.scene().shape(7));
            assertThat(scene.lights()).hasSize(2);
            assertThat(pixels(scene)).isEqualTo(pixels(view.readInFull().scene()));
        }
    }

    @Test
    void anAddedOrRemovedObjectIsReadInFullWithItsChangesTold() {
        try (PatchedView view = view()) {
            SceneReuse.Revision added = view.patch("[{\"op\": \"add\", \"path\": \"/objects/2\", \"value\": {\"type\": \"box\"}}]");
            assertThat(view.assembled()).isZero();
            assertThat(added.origins()).startsWith(0, 1, -1, 2, 3);
            assertThat(pixels(added.compiled().scene())).isEqualTo(pixels(view.readInFull().scene()));
            SceneReuse.Revision removed = view.patch("[{\"op\": \"remove\", \"path\": \"/objects/2\"}]");
            assertThat(removed.origins()).startsWith(0, 1, 3, 4);
        }
    }
}

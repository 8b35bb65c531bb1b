package studio.server.preview;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.util.Map;
import java.util.Random;
import java.util.function.Function;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;

import studio.engine.geometry.TriangleMesh;
import studio.engine.memory.MemoryGate;
import studio.engine.mesh.MeshShapes;
import studio.engine.mesh.ObjWriter;
import studio.engine.render.Film;
import studio.engine.render.RenderSettings;
import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.engine.sampler.Sampler;
import studio.engine.scene.Scene;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.format.InvalidSceneException;
import studio.server.scene.reading.LazyValidation;
import studio.server.system.MemoryBudget;

/** A live view reads only the objects a revision changed, and gets the scene reading it all gives. */
class SceneReuseTest {

    private static final LazyValidation VALIDATION = new LazyValidation();
    private static final SceneCompiler COMPILER = SceneCompiler.standalone(VALIDATION);
    private static final Function<byte[], CompiledScene> READ =
            json -> COMPILER.compile(CompileRequest.of(json).overriding(Map.of("image.width", 48, "image.height", 36)).onThreads(1));

    @AfterAll
    static void close() {
        VALIDATION.close();
    }

    /** n spheres of several materials, a floor and a box, two lights; sphere {@code moved} shifted by dx. */
    private static String scene(int n, int moved, double dx, String light) {
        Random random = new Random(3);
        String[] materials = {"{\"type\": \"plastic\", \"color\": \"#cc3333\"}", "{\"type\": \"mirror\"}",
                "{\"type\": \"metal\", \"color\": \"#aabbcc\"}", "{\"type\": \"chalk\"}"};
        StringBuilder objects = new StringBuilder("{\"type\": \"plane\"},\n");
        for (int i = 0; i < n; i++) {
            double x = random.nextDouble() * 6 - 3 + (i == moved ? dx : 0);
            objects.append(String.format(java.util.Locale.ROOT,
                    "  {\"type\": \"sphere\", \"center\": [%.4f, %.4f, %.4f], \"radius\": 0.15, \"material\": %s},%n",
                    x, 0.2 + random.nextDouble() * 2, random.nextDouble() * -4, materials[i % materials.length]));
        }
        objects.append("  {\"type\": \"box\", \"center\": [0, 0.5, 1], \"rotation\": [0, 30, 0]}");
        return """
                {"image": {"width": 320, "height": 240}, "render": {"samples": 4, "sampler": "jittered"},
                 "camera": {"position": [0, 2, 6], "lookAt": [0, 1, -1]},
                 "lights": [%s, {"type": "point", "position": [-3, 4, 2], "intensity": 0.5}],
                 "objects": [%s]}
                """.formatted(light, objects);
    }

    private static final String LIGHT = "{\"type\": \"point\", \"position\": [3, 5, 4]}";

    private static PreviewRequest request(long revision, String scene) {
        return request(revision, scene, 48, 36);
    }

    /** The live view's message for the scene, read as the view reads it (the objects found in the same pass). */
    private static PreviewRequest request(long revision, String scene, int width, int height) {
        String message = "{\"revision\": " + revision + ", \"width\": " + width + ", \"height\": " + height
                + ", \"scene\": " + scene + "}";
        return PreviewRequest.parse(message.getBytes(StandardCharsets.UTF_8), 2048, 2048);
    }

    /** Every bit of every pixel of a small render. */
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
    void aMovedObjectIsReadAloneAndTheSceneIsTheOneReadingItAllGives() {
        CountedReads reads = new CountedReads(READ);
        try (SceneReuse reuse = new SceneReuse(MemoryBudget.unlimited())) {
            CompiledScene first = reuse.compile(request(1, scene(300, 7, 0, LIGHT)), MemoryGate.UNLIMITED, reads).compiled();
            String movedJson = scene(300, 7, 0.4, LIGHT);

            CompiledScene moved = reuse.compile(request(2, movedJson), MemoryGate.UNLIMITED, reads).compiled();

            assertThat(reads.holding(302)).as("the first revision read in full, the second not").isOne();
            assertThat(reads.holding(1, 1)).as("the moved sphere read alone").isOne();
            assertThat(moved.scene().objectCount()).isEqualTo(302);
            assertThat(moved.scene().shape(3)).as("an unchanged object is kept").isSameAs(first.scene().shape(3));
            assertThat(moved.scene().shape(8)).isNotEqualTo(first.scene().shape(8)).isEqualTo(
                    READ.apply(movedJson.getBytes(StandardCharsets.UTF_8)).scene().shape(8));
            assertThat(moved.settings()).isEqualTo(first.settings());
            CompiledScene readInFull = READ.apply(movedJson.getBytes(StandardCharsets.UTF_8));
            assertThat(pixels(moved.scene())).isEqualTo(pixels(readInFull.scene()));
            assertThat(pixels(moved.scene())).isNotEqualTo(pixels(first.scene()));
        }
    }

    @Test
    void aRevisionLikeTheLastIsTheLastScene() {
        try (SceneReuse reuse = new SceneReuse(MemoryBudget.unlimited())) {
            CompiledScene first = reuse.compile(request(1, scene(300, 7, 0, LIGHT)), MemoryGate.UNLIMITED, READ).compiled();

            assertThat(reuse.compile(request(2, scene(300, 7, 0, LIGHT)), MemoryGate.UNLIMITED, READ).compiled()).isSameAs(first);
        }
    }

    @Test
    void changesBesideTheObjectsOrToManyOfThemAreReadInFull() {
        CountedReads reads = new CountedReads(READ);
        try (SceneReuse reuse = new SceneReuse(MemoryBudget.unlimited())) {
            CompiledScene first = reuse.compile(request(1, scene(300, 7, 0, LIGHT)), MemoryGate.UNLIMITED, reads).compiled();
            String lightMoved = LIGHT.replace("[3, 5, 4]", "[2, 5, 4]");

            CompiledScene relit = reuse.compile(request(2, scene(300, 7, 0, lightMoved)), MemoryGate.UNLIMITED, reads).compiled();
            assertThat(relit.scene().shape(3)).isNotSameAs(first.scene().shape(3));
            assertThat(relit.scene().lights().get(0).position().x()).isEqualTo(2);

            String many = scene(300, 7, 0, lightMoved).replace("\"radius\": 0.15", "\"radius\": 0.16");
            CompiledScene grown = reuse.compile(request(3, many), MemoryGate.UNLIMITED, reads).compiled();
            assertThat(grown.scene().shape(3)).isNotSameAs(relit.scene().shape(3));

            CountedReads larger = new CountedReads(
                    json -> COMPILER.compile(CompileRequest.of(json).overriding(Map.of("image.width", 64, "image.height", 48)).onThreads(1)));
            CompiledScene otherSize = reuse.compile(request(4, many, 64, 48), MemoryGate.UNLIMITED, larger).compiled();
            assertThat(otherSize.settings().width()).isEqualTo(64);
            assertThat(reads.holding(302)).as("each revision read in full").isEqualTo(3);
            assertThat(larger.holding(302)).isOne();
        }
    }

    @Test
    void aChangedObjectThatDoesNotReadGetsItsProblemByItsPathInTheWholeScene() {
        CountedReads reads = new CountedReads(READ);
        try (SceneReuse reuse = new SceneReuse(MemoryBudget.unlimited())) {
            reuse.compile(request(1, scene(300, 7, 0, LIGHT)), MemoryGate.UNLIMITED, reads).compiled();
            String bad = scene(300, 7, 0, LIGHT).replaceFirst("\"radius\": 0.15", "\"radius\": -1");

            assertThatThrownBy(() -> reuse.compile(request(2, bad), MemoryGate.UNLIMITED, reads).compiled()).isInstanceOfSatisfying(
                    InvalidSceneException.class, e -> assertThat(e.problems()).anySatisfy(
                            p -> assertThat(p.field()).isEqualTo("objects[1].radius")));
            // the last scene that read is still kept
            reuse.compile(request(3, scene(300, 7, 0.2, LIGHT)), MemoryGate.UNLIMITED, reads).compiled();
            assertThat(reads.holding(302)).as("only the first revision read in full").isOne();
        }
    }

    @Test
    void smallScenesAreReusedTooAndAKeptSceneHoldsMemoryUntilTheViewCloses() {
        MemoryBudget memory = new MemoryBudget(1L << 30);
        SceneReuse reuse = new SceneReuse(memory);
        CountedReads reads = new CountedReads(READ);
        reuse.compile(request(1, scene(10, 7, 0, LIGHT)), MemoryGate.UNLIMITED, reads).compiled();
        SceneReuse.Revision small = reuse.compile(request(2, scene(10, 7, 0.4, LIGHT)), MemoryGate.UNLIMITED, reads);
        assertThat(reads.holding(12)).as("the second revision not read in full").isOne();
        assertThat(small.origins()).as("the moved sphere told, the others kept in place")
                .containsExactly(0, 1, 2, 3, 4, 5, 6, 7, -1, 9, 10, 11);
        assertThat(memory.reserved()).isPositive();

        reuse.compile(request(3, scene(300, 7, 0, LIGHT)), MemoryGate.UNLIMITED, READ).compiled();
        assertThat(memory.reserved()).isPositive();
        reuse.close();
        assertThat(memory.reserved()).isZero();
        reuse.compile(request(4, scene(300, 7, 0.4, LIGHT)), MemoryGate.UNLIMITED, READ).compiled();
        assertThat(memory.reserved()).as("nothing kept after close").isZero();
    }

    /** An inline mesh (a 3,840-triangle torus knot, about 200 kB of OBJ) at x, scaled, beside a sphere over a floor. */
    private static String meshScene(String obj, double x, double scale) {
        return """
                {"image": {"width": 320, "height": 240}, "render": {"samples": 4, "sampler": "jittered"},
                 "camera": {"position": [0, 2, 6], "lookAt": [0, 0.5, 0]},
                 "lights": [%s],
                 "objects": [{"type": "plane"},
                             {"type": "mesh", "obj": "%s", "position": [%s, 0.8, 0], "scale": %s,
                              "material": {"type": "metal", "color": "#c0a060"}},
                             {"type": "sphere", "center": [1.5, 0.5, 0.5], "radius": 0.5}]}
                """.formatted(LIGHT, obj, x, scale);
    }

    private static String knot() {
        StringBuilder text = new StringBuilder();
        try {
            ObjWriter.write(MeshShapes.torusKnot(2, 3, 120, 16), text);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
        return text.toString().replace("\n", "\\n");
    }

    @Test
    void aMovedInlineMeshKeepsItsTextUnreadAndItsTree() {
        String knot = knot();
        CountedReads reads = new CountedReads(READ);
        try (SceneReuse reuse = new SceneReuse(MemoryBudget.unlimited())) {
            CompiledScene first = reuse.compile(request(1, meshScene(knot, 0, 0.4)), MemoryGate.UNLIMITED, reads).compiled();
            String movedJson = meshScene(knot, 0.25, 0.4);

            CompiledScene moved = reuse.compile(request(2, movedJson), MemoryGate.UNLIMITED, reads).compiled();

            assertThat(reads.holding(3)).as("the moved mesh read alone").isOne();
            TriangleMesh mesh = (TriangleMesh) moved.scene().shape(1);
            assertThat(mesh.buildNanos()).as("the kept mesh moved, its tree not built again").isZero();
            assertThat(mesh.triangleCount()).isEqualTo(((TriangleMesh) first.scene().shape(1)).triangleCount());
            assertThat(moved.scene().shape(2)).isSameAs(first.scene().shape(2));
            CompiledScene readInFull = READ.apply(movedJson.getBytes(StandardCharsets.UTF_8));
            assertThat(mesh.positions()).isEqualTo(((TriangleMesh) readInFull.scene().shape(1)).positions());
            assertThat(pixels(moved.scene())).isEqualTo(pixels(readInFull.scene()));
            assertThat(pixels(moved.scene())).isNotEqualTo(pixels(first.scene()));

            // scaled, or another text: read in full
            reuse.compile(request(3, meshScene(knot, 0.25, 0.5)), MemoryGate.UNLIMITED, reads).compiled();
            reuse.compile(request(4, meshScene(knot + "# another text\\n", 0.25, 0.5)), MemoryGate.UNLIMITED, reads).compiled();
            assertThat(reads.holding(3)).as("the revisions but the second read in full").isEqualTo(3);
        }
    }
}

package studio.server.preview;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.function.Function;

import tools.jackson.databind.JsonNode;

import studio.engine.memory.MemoryGate;
import studio.engine.mesh.MeshShapes;
import studio.engine.mesh.ObjWriter;
import studio.engine.render.Film;
import studio.engine.render.RenderRequest;
import studio.engine.render.RenderSettings;
import studio.engine.render.Renderer;
import studio.engine.sampler.Sampler;
import studio.engine.scene.Scene;
import studio.server.scene.compiling.CompiledScene;
import studio.server.system.MemoryBudget;

/**
 * A live view's kept scene and patch base after a whole revision, and the patches that follow, as
 * {@link PreviewSession} drives {@link SceneReuse} and {@link PatchBase}; the scene can be read in
 * full from the patched tree, as {@code POST /api/render} reads it.
 */
final class PatchedView implements AutoCloseable {

    final SceneReuse reuse = new SceneReuse(MemoryBudget.unlimited());
    final PatchBase base = new PatchBase(MemoryBudget.unlimited(), 1 << 20);
    /** The whole revision's scene. */
    final CompiledScene first;
    private final int width, height;
    private final Function<byte[], CompiledScene> read;
    private final CountedReads reads;
    private JsonNode tree;
    private long revision = 1;
    private long readWhole;

    /** A view of {@code width} x {@code height} sent {@code sceneJson} whole; {@code read} compiles a scene at that size. */
    PatchedView(String sceneJson, int width, int height, Function<byte[], CompiledScene> read) {
        this.width = width;
        this.height = height;
        this.read = read;
        this.reads = new CountedReads(read);
        PreviewRequest request = parse("{\"revision\": 1, \"width\": " + width + ", \"height\": " + height
                + ", \"scene\": " + sceneJson + "}");
        base.whole(1, request.scene());
        first = reuse.compile(request, MemoryGate.UNLIMITED, reads).compiled();
        readWhole = reads.holding(first.scene().objectCount());
        base.compiled();
    }

    /** The next revision: these RFC 6902 operations against the last one. */
    SceneReuse.Revision patch(String operations) {
        PreviewRequest request = parse("{\"revision\": " + (revision + 1) + ", \"base\": " + revision + ", \"width\": "
                + width + ", \"height\": " + height + ", \"patch\": " + operations + "}");
        revision++;
        tree = base.patch(revision, request.base(), request.patch());
        int from = reads.reads();
        SceneReuse.Revision compiled = reuse.compilePatched(base.compiledTree(), tree, base.origins(), request,
                MemoryGate.UNLIMITED, reads);
        readWhole += reads.holding(compiled.compiled().scene().objectCount(), from) > 0 ? 1 : 0;
        base.compiled();
        return compiled;
    }

    /**
     * Revisions so far (the whole first one among them) for which a scene with all of the
     * revision's objects was read, not the changed objects alone.
     */
    long readWhole() {
        return readWhole;
    }

    /** Revisions so far assembled from the kept scene: the patches for which no whole scene was read. */
    long assembled() {
        return revision - readWhole;
    }

    /** The patched scene read in full. */
    CompiledScene readInFull() {
        return read.apply(TreeObjects.bytes(tree));
    }

    private static PreviewRequest parse(String message) {
        return PreviewRequest.parse(message.getBytes(StandardCharsets.UTF_8), 2048, 2048);
    }

    /** A 960-triangle torus knot's OBJ text, escaped for a JSON string: the patch tests' mesh. */
    static String knotObj() {
        StringBuilder knot = new StringBuilder();
        try {
            ObjWriter.write(MeshShapes.torusKnot(2, 3, 60, 8), knot);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return knot.toString().replace("\n", "\\n");
    }

    /** Every channel of {@code scene} rendered at {@code width} x {@code height}, jittered at {@code samples}, seed 7. */
    static double[] pixels(Scene scene, int width, int height, int samples) {
        Film film = Renderer.render(RenderRequest.of(scene, new RenderSettings(width, height, Sampler.of("jittered", samples), 4,
                2, 7L, RenderSettings.DEFAULT_MIN_PATH_WEIGHT, 0))).film();
        double[] all = new double[width * height * 3];
        for (int y = 0, k = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                for (int c = 0; c < 3; c++) {
                    all[k++] = film.get(x, y, c);
                }
            }
        }
        return all;
    }

    @Override
    public void close() {
        reuse.close();
        base.close();
    }
}

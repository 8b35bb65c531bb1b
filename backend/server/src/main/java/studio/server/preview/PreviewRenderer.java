package studio.server.preview;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BooleanSupplier;

import org.springframework.http.HttpStatus;
import org.springframework.http.ProblemDetail;
import org.springframework.web.ErrorResponse;

import studio.engine.image.ImageEncoder;
import studio.engine.memory.MemoryGate;
import studio.engine.render.Film;
import studio.engine.render.PixelPaths;
import studio.engine.render.RenderListener;
import studio.engine.render.RenderRequest;
import studio.engine.render.RenderResult;
import studio.engine.render.RenderSettings;
import studio.engine.scene.MeshLightBuffers;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;
import studio.server.render.RenderBudget;
import studio.server.render.RenderMetrics;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.format.InvalidSceneException;
import studio.server.system.IntakeMemory;
import studio.server.system.MemoryBudget;
import studio.server.system.MemoryBusyException;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * What every live view shares: reading a revision's scene as {@code POST /api/render} does, rendering
 * one pass within the render budget, encoding its frame, and the problems a view is sent.
 */
final class PreviewRenderer {

    /** JPEG quality of the passes before the last. */
    static final double COARSE_QUALITY = 0.85;

    private final SceneCompiler compiler;
    private final RenderBudget budget;
    private final int threads;
    private final PreviewProperties limits;
    private final JsonMapper json;

    PreviewRenderer(SceneCompiler compiler, RenderBudget budget, int threads, PreviewProperties limits,
                    JsonMapper json) {
        this.compiler = compiler;
        this.budget = budget;
        this.threads = threads;
        this.limits = limits;
        this.json = json;
    }

    PreviewProperties limits() {
        return limits;
    }

    MemoryBudget memory() {
        return budget.memory();
    }

    /**
     * The scene of a whole revision at the view's size, its building drawn on {@code memory}, which
     * holds the message's reading already (as a request body's intake does); assembled from the
     * view's last scene where only some objects changed ({@link SceneReuse}).
     *
     * @throws InvalidSceneException as {@code POST /api/render} would refuse it
     * @throws org.springframework.web.ErrorResponseException 503 while the memory is taken, 413 if it could never fit
     */
    SceneReuse.Revision compile(PreviewRequest request, IntakeMemory memory, SceneReuse reuse) {
        return reuse.compile(request, memory, json -> compile(json, request, memory));
    }

    /**
     * As {@link #compile(PreviewRequest, IntakeMemory, SceneReuse)}, for a patched revision: the
     * scene {@code after}, patched from {@code before} (the last revision compiled) with the
     * changes {@code changes} tells (null: not known, read in full).
     */
    SceneReuse.Revision compilePatched(PreviewRequest request, JsonNode before, JsonNode after, ObjectOrigins changes,
                                       IntakeMemory memory, SceneReuse reuse) {
        return reuse.compilePatched(before, after, changes, request, memory, json -> compile(json, request, memory));
    }

    /** Scene JSON read at the request's view size, as {@code POST /api/render} reads it. */
    private CompiledScene compile(byte[] json, PreviewRequest request, IntakeMemory memory) {
        Map<String, Object> overrides = new HashMap<>();
        if (request.width() > 0) {
            overrides.put("image.width", request.width());
        }
        if (request.height() > 0) {
            overrides.put("image.height", request.height());
        }
        overrides.put("image.format", "png");
        return compiler.compile(CompileRequest.of(json).overriding(overrides).onThreads(threads).within(memory));
    }

    /**
     * Reserves the render memory of the film (and the scene's share) that passes with these
     * settings render into.
     *
     * @return the reservation, or null if the render memory is taken right now
     * @throws InvalidSceneException if it could never fit the render memory
     */
    MemoryBudget.Reservation reserve(CompiledScene scene, RenderSettings settings) {
        return budget.reserve(passScene(scene, settings));
    }

    /**
     * {@code scene} with its meshes given the light buffers a render at its own settings pays for
     * ({@link MeshLightBuffers}), their memory asked of {@code memory}; itself if none was built.
     * A revision assembled from the last gives a moved mesh only a one-sample render's, so the
     * first frames do not wait for buffers that only the finer passes win back (PatchRevisionBench
     * {@code --mesh}: building them was about three quarters of compiling a moved mesh's revision).
     */
    CompiledScene lit(CompiledScene scene, MemoryBudget.Reservation memory) {
        Scene kept = scene.scene();
        List<SceneObject> objects = new ArrayList<>(kept.objectCount());
        for (int i = 0; i < kept.objectCount(); i++) {
            objects.add(new SceneObject(kept.shape(i), kept.material(i)));
        }
        MemoryGate gate = new MemoryGate() {
            @Override
            public void reserve(long bytes) {
                if (!memory.tryGrow(bytes)) {
                    throw new MemoryBusyException();
                }
            }

            @Override
            public boolean tryReserve(long bytes) {
                return memory.tryGrow(bytes);
            }
        };
        List<SceneObject> lit = MeshLightBuffers.forRender(objects, kept.lights(), scene.settings().cameraSamples(), gate);
        for (int i = 0; i < lit.size(); i++) {
            if (lit.get(i).shape() != kept.shape(i)) {
                return new CompiledScene(Scene.reusing(kept, kept.camera(), lit, kept.lights(), kept.background(),
                        kept.ambient()), scene.settings(), scene.format(), scene.quality(), scene.fileStem());
            }
        }
        return scene;
    }

    /**
     * Renders one pass into {@code film} (of the pass's settings, its memory reserved by
     * {@link #reserve}), leaving out the pixels known to {@code paths} (null: none) and recording
     * the others' there, and encodes the pass's pixels as a frame message.
     *
     * @throws studio.engine.render.RenderCancelledException when {@code superseded} turns true first
     * @throws studio.server.render.RenderTimeExceededException past the render time budget
     */
    byte[] render(CompiledScene scene, PreviewPass pass, Film film, PixelPaths paths, long revision,
                  long receivedNanos, BooleanSupplier superseded) {
        // into the pass's film itself: a request of the scene's own (CompiledScene.request) would first
        // allocate a film of the view's size for nothing, 7.4 MB at 640x480 for every pass of every revision
        RenderResult rendered = budget.render(new RenderRequest(scene.scene(), pass.settings(), film, pass.pixels(),
                pass.except(), paths, RenderListener.NONE, superseded));
        budget.metrics().rendered(RenderMetrics.Kind.LIVE_VIEW, rendered);
        try {
            ByteArrayOutputStream image = new ByteArrayOutputStream();
            if (pass.last()) {
                ImageEncoder.writePng(ImageEncoder.toImage(film, pass.pixels()), image);
            } else {
                ImageEncoder.writeJpeg(ImageEncoder.toJpegImage(film, pass.pixels()), COARSE_QUALITY, image);
            }
            PreviewFrame frame = new PreviewFrame(revision, pass.number(), pass.frameWidth(), pass.frameHeight(),
                    pass.settings().sampler().samplesPerPixel(), pass.last(), pass.last() ? "png" : "jpeg",
                    (System.nanoTime() - receivedNanos) / 1_000_000);
            return frame.encode(image.toByteArray());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static CompiledScene passScene(CompiledScene scene, RenderSettings settings) {
        return new CompiledScene(scene.scene(), settings, "png", 1, scene.fileStem());
    }

    /**
     * {@code {"revision": n, "problem": {...}}} for a refusal that carries its own problem: an invalid
     * message or scene ({@link InvalidSceneException}), memory that is taken, ...
     */
    String problem(Long revision, ErrorResponse refusal) {
        return problem(revision, refusal.getBody());
    }

    /** {@code {"revision": n, "problem": {...}}} for a problem of another kind. */
    String problem(Long revision, HttpStatus status, String title, String detail) {
        ProblemDetail problem = ProblemDetail.forStatusAndDetail(status, detail);
        problem.setTitle(title);
        return problem(revision, problem);
    }

    private String problem(Long revision, ProblemDetail problem) {
        problem.setInstance(java.net.URI.create("/api/preview"));
        Map<String, Object> message = new HashMap<>();
        message.put("revision", revision);
        message.put("problem", problem);
        return json.writeValueAsString(message);
    }
}

package studio.server.render;

import java.util.concurrent.Semaphore;

import studio.engine.render.RenderResult;
import studio.engine.render.Renderer;
import studio.server.scene.CompiledScene;
import studio.server.scene.SceneCompiler;

/** Renders scenes for the synchronous API, at most a configured number at once. */
public final class RenderService {

    private final SceneCompiler compiler;
    private final Semaphore slots;
    private final int threads;

    /**
     * @param concurrentRenders renders allowed at once; more are refused ({@link RenderBusyException})
     * @param threads           worker threads per render, 0 for all cores
     */
    public RenderService(SceneCompiler compiler, int concurrentRenders, int threads) {
        this.compiler = compiler;
        this.slots = new Semaphore(concurrentRenders);
        this.threads = threads;
    }

    /** Validates, renders and encodes a scene given as JSON. */
    public RenderedImage render(byte[] sceneJson) {
        CompiledScene compiled = compiler.compile(sceneJson, java.util.Map.of(), threads);
        if (!slots.tryAcquire()) {
            throw new RenderBusyException();
        }
        try {
            RenderResult result = Renderer.render(compiled.scene(), compiled.settings());
            byte[] bytes = ImageFiles.encode(result.film(), compiled.format(), compiled.quality());
            return new RenderedImage(bytes, compiled.mediaType(), compiled.fileName(), compiled.settings().width(),
                    compiled.settings().height(), result.elapsedMillis(), result.raysPerSecond());
        } finally {
            slots.release();
        }
    }
}

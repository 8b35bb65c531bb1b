package studio.server.system;

import java.time.Duration;

import org.springframework.boot.context.properties.ConfigurationProperties;
import org.springframework.boot.context.properties.bind.DefaultValue;
import org.springframework.util.unit.DataSize;

/**
 * The service's settings (application.properties, or environment variables such as
 * STUDIO_LIMITS_MAXWIDTH), every one with its default, in one place as an operator reads them.
 * Plain values only: each feature's configuration turns its part into its own types (the scene
 * limits, the job settings, ...), so this package knows none of them.
 *
 * @param concurrentRenders synchronous renders at once; more get 503 with Retry-After
 * @param renderThreads     worker threads per render, 0 for all cores
 * @param renderMemory      the heap that renders and request bodies may hold at once; 0 for half of the maximum
 *                          heap; beyond it 503 (a render) or 429 (a body)
 * @param warmUp            at start-up, before the port opens, the longest the service may spend rendering
 *                          its small training scenes, so that the first request runs compiled code; 0s for none
 */
@ConfigurationProperties("studio")
public record StudioProperties(@DefaultValue Limits limits, @DefaultValue Jobs jobs, @DefaultValue Assets assets,
                               @DefaultValue("2") int concurrentRenders, @DefaultValue("0") int renderThreads,
                               @DefaultValue("0B") DataSize renderMemory, @DefaultValue("10s") Duration warmUp) {

    /**
     * Render jobs: how many run at once, how many wait, how long results are kept, and on shutdown
     * how long running jobs may go on before they are cancelled.
     *
     * @param concurrent    render jobs (POST /api/jobs) that run at once
     * @param queue         jobs that may wait to run; more get 429 with Retry-After
     * @param keepFinished  how long a finished job and its image are kept
     * @param maxFinished   finished jobs kept at most; the oldest is dropped first
     * @param abandonAfter  a job that nobody has asked about for this long is cancelled
     * @param shutdownGrace on shutdown, how long running renders (jobs and POST /api/render) may go on
     *                      before they are cancelled; queued jobs are cancelled at once
     */
    public record Jobs(@DefaultValue("1") int concurrent, @DefaultValue("8") int queue,
                       @DefaultValue("15m") Duration keepFinished, @DefaultValue("50") int maxFinished,
                       @DefaultValue("2m") Duration abandonAfter, @DefaultValue("20s") Duration shutdownGrace) {
    }

    /**
     * Limits on one scene, one request and one render.
     *
     * @param maxWidth        the widest image a scene may ask for, in pixels
     * @param maxHeight       the tallest image a scene may ask for, in pixels
     * @param maxSamples      the most samples per pixel a scene may ask for
     * @param maxDepth        the deepest recursion (reflection and refraction bounces) a scene may ask for
     * @param maxObjects      the most objects in one scene
     * @param maxLights       the most lights in one scene
     * @param maxTriangles    the most triangles of all of a scene's meshes together
     * @param maxBodyBytes    the largest request body (and live-view message), inline meshes included (about
     *                        70 bytes a triangle); larger ones get 413
     * @param maxPixelSamples the render budget: width times height times samples of one render
     * @param maxRenderTime   the wall time one render may take; then it stops and says so (422)
     * @param bodyGrace       how long any request body may take to arrive
     * @param minBodyRate     beyond that, how fast (per second, on average) it must keep arriving; slower
     *                        ones get 408
     */
    public record Limits(@DefaultValue("4096") int maxWidth, @DefaultValue("4096") int maxHeight,
                         @DefaultValue("1024") int maxSamples, @DefaultValue("16") int maxDepth,
                         @DefaultValue("100000") int maxObjects, @DefaultValue("100") int maxLights,
                         @DefaultValue("2000000") int maxTriangles, @DefaultValue("33554432") long maxBodyBytes,
                         @DefaultValue("268435456") long maxPixelSamples, @DefaultValue("5m") Duration maxRenderTime,
                         @DefaultValue("10s") Duration bodyGrace, @DefaultValue("256KB") DataSize minBodyRate) {
    }

    /**
     * Assets (POST /api/assets): bytes kept by their content's hash, in the service's memory.
     *
     * @param maxBytes      the largest asset; larger ones get 413 (a body is also held to limits.max-body-bytes)
     * @param maxStoreBytes all assets kept at once, at most a quarter of the memory budget (render-memory); when
     *                      full, the least recently used are dropped
     * @param maxPixels     the most pixels (width times height) an image asset may declare in its header
     */
    public record Assets(@DefaultValue("16MB") DataSize maxBytes, @DefaultValue("256MB") DataSize maxStoreBytes,
                         @DefaultValue("67108864") long maxPixels) {
    }

    /** The memory budget: {@link #renderMemory}, or half of the maximum heap when that is 0. */
    public MemoryBudget memoryBudget() {
        return renderMemory.toBytes() > 0 ? new MemoryBudget(renderMemory.toBytes()) : MemoryBudget.ofHeapShare(0.5);
    }
}

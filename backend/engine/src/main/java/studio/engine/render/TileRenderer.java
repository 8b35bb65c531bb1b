package studio.engine.render;

import studio.engine.scene.Scene;

/**
 * A render's unit of work and the worker that does it: renders any tile of a render (its
 * rectangle, optionally a lattice of its pixels) into a film. Each pixel's samples are seeded from
 * the pixel, so a tile comes out the same, bit for bit, whichever worker renders it and in
 * whatever order; a render is therefore a set of independent tile tasks, run here by
 * {@link Renderer}'s pool, and by anything else that can hand a worker a tile. One per thread: a
 * worker holds its own integrator, random stream and sample buffers, and allocates nothing per
 * tile.
 */
public final class TileRenderer {

    private final SampleTracer tracer;
    private final TileSampling sampling;
    private final RenderSettings settings;
    private final StopSignal stop;

    /**
     * A worker of its own: it shares no edge samples with other workers (under progressive sobol
     * each tile traces its one-pixel ring itself, to the same values) and stops only by {@link #stop}.
     */
    public TileRenderer(Scene scene, RenderSettings settings) {
        this(scene, settings, null, new StopSignal());
    }

    /** A worker of a render whose tiles share {@code borders} (or null) and {@code stop}. */
    TileRenderer(Scene scene, RenderSettings settings, TileBorders borders, StopSignal stop) {
        this.stop = stop;
        tracer = new SampleTracer(scene, settings, stop);
        sampling = TileSampling.of(settings, tracer, borders, stop);
        this.settings = settings;
    }

    /**
     * Renders what the request asks: the tile's pixels on its lattice, not on its {@code except}
     * and not known to its {@code paths} into its film, recording the rendered pixels' rays in those
     * paths; the film's other pixels are left as they are. A whole tile is
     * {@code render(TileRequest.whole(film, tile))}.
     *
     * @return how many samples came out non-finite (dropped; the pixel is the mean of the others)
     * @throws IllegalArgumentException under adaptive sampling, which renders every pixel
     * @throws RenderCancelledException once this worker's render is stopped
     */
    public long render(TileRequest request) {
        requireLattice(settings, request.pixels(), request.except(), request.paths());
        return sampling.render(request);
    }

    /**
     * @throws IllegalArgumentException unless the pixels are every pixel and none are kept, or the
     *                                  sampling is fixed; or if the paths are not the settings' size
     */
    static void requireLattice(RenderSettings settings, PixelLattice pixels, PixelLattice except, PixelPaths paths) {
        if (settings.adaptive() && (!pixels.equals(PixelLattice.ALL) || except != null || paths != null)) {
            throw new IllegalArgumentException("adaptive sampling renders every pixel");
        }
        if (paths != null && (paths.width() != settings.width() || paths.height() != settings.height())) {
            throw new IllegalArgumentException("the pixel paths are " + paths.width() + "x" + paths.height()
                    + ", the settings " + settings.width() + "x" + settings.height());
        }
    }

    /** Stops the tile being rendered within a camera sample, and every later one. */
    public void stop() {
        stop.raise();
    }

    /** Rays this worker has traced. */
    public long rays() {
        return tracer.rays();
    }

    /** Camera samples this worker has taken. */
    public long samples() {
        return sampling.samples();
    }
}

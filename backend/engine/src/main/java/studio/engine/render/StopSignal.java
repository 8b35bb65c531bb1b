package studio.engine.render;

/**
 * A render's decision to stop, shared by its workers. The caller's cancel condition may be slow
 * (it may read a connection), so the workers never ask it inside a tile: the render's own thread
 * asks it every {@value Renderer#POLL_MILLIS} ms and raises this signal, and each worker reads the
 * signal, one volatile field, before every camera sample. A tile therefore stops within one
 * sample of the signal, whatever its size (a deep glass-and-mirror sample is milliseconds); the
 * check, one volatile read, costs nothing measurable (still-life renders with and without it).
 */
final class StopSignal {

    private volatile boolean raised;

    void raise() {
        raised = true;
    }

    boolean raised() {
        return raised;
    }

    /**
     * Ends the tile being rendered once the signal is raised. A tile stopped on its ring gives up the
     * edge pixel it holds on the way out (see {@link TileBorders#abandon}).
     *
     * @throws RenderCancelledException if the signal is raised
     */
    void check() {
        if (raised) {
            throw new RenderCancelledException();
        }
    }
}

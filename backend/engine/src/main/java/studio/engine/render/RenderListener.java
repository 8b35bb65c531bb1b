package studio.engine.render;

/** Hears about a render's progress. Called from worker threads, so implementations must be thread-safe. */
@FunctionalInterface
public interface RenderListener {

    RenderListener NONE = (film, tile, done, total) -> { };

    /** One more tile is finished; its pixels are in {@code film}. {@code done} counts finished tiles. */
    void tileFinished(Film film, TileRect tile, int done, int total);
}

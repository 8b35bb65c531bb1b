package studio.server.cluster;

import java.util.BitSet;
import java.util.List;
import java.util.Map;

import studio.engine.render.Film;
import studio.engine.render.RenderListener;
import studio.engine.render.TileRect;

/**
 * A job's film on its coordinator as its tiles arrive from the cluster's workers: each tile once,
 * reported to the job's listener in the order it arrived; what is done is this record, not the
 * cluster's maps.
 */
final class TileAssembly {

    final List<TileRect> tiles;
    final Film film;
    final RenderListener listener;
    /** The tiles each member rendered. */
    final Map<String, Integer> count;
    /** The tiles in the film. */
    final BitSet done = new BitSet();
    int doneCount;
    long rays, samples, nonFinite;

    TileAssembly(List<TileRect> tiles, Film film, RenderListener listener, Map<String, Integer> count) {
        this.tiles = tiles;
        this.film = film;
        this.listener = listener;
        this.count = count;
    }

    /**
     * Why a result read from the cluster cannot be used, or null if it can: its index must be one of
     * the job's tiles, and a rendered tile must have three finite values for each of the tile's pixels.
     */
    String problem(TileResult result) {
        if (result.index() < 0 || result.index() >= tiles.size()) {
            return "no such tile: " + result.index();
        }
        if (result.failed()) {
            return null;
        }
        TileRect tile = tiles.get(result.index());
        double[] rgb = result.rgb();
        if (rgb == null || rgb.length != 3 * tile.width() * tile.height()) {
            return "tile " + result.index() + " has " + (rgb == null ? 0 : rgb.length) + " values, not "
                    + 3 * tile.width() * tile.height();
        }
        for (double value : rgb) {
            if (!Double.isFinite(value)) {
                return "tile " + result.index() + " has a value that is not finite";
            }
        }
        return null;
    }

    /** Puts a tile's result into the film, unless it failed or the tile is done already ({@link #problem} first). */
    void accept(TileResult result) {
        if (result.failed() || done.get(result.index())) {
            return;
        }
        TileRect tile = tiles.get(result.index());
        // a call, not a loop here: a loop's backedges had C2 compile this method, with the listener's
        // tile encoding inlined, during a fresh member's first job
        film.setPixels(tile, result.rgb());
        done.set(result.index());
        doneCount++;
        rays += result.rays();
        samples += result.samples();
        nonFinite += result.nonFinite();
        count.merge(result.worker(), 1, Integer::sum);
        listener.tileFinished(film, tile, doneCount, tiles.size());
    }
}

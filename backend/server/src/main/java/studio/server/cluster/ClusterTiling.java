package studio.server.cluster;

import java.util.ArrayList;
import java.util.List;

import studio.engine.render.Renderer;
import studio.engine.render.TileRect;

/**
 * A cluster job's tiles, in the order they are queued: the image's top rows in tiles of twice the
 * job's tile size a side, then at least its last {@value #TAIL_FRACTION_DIVISOR}rd of rows (two at
 * the least) in tiles of the job's size. A tile costs its workers and its owner the same few round
 * trips however large it is, so the large tiles take a quarter of them for most of the image, and
 * the small ones at the end keep the job's tail as short as small tiles everywhere would
 * ({@code scripts/cluster-cpu.py}, docs/cluster.md, "Where two members' CPU goes"). The pixels do not depend on the tiling: each is seeded from
 * itself. A job's tiling is fixed by its image's size and its record's tile size, so every member
 * (and one that takes the job over) cuts it the same way.
 */
final class ClusterTiling {

    /** At least 1/this of the rows of small tiles (rounded up) end the job. */
    static final int TAIL_FRACTION_DIVISOR = 3;
    /** At least this many rows of small tiles end the job. */
    static final int MIN_TAIL_ROWS = 2;

    private ClusterTiling() {
    }

    /** The tiles of a width x height image with small tiles of size x size, large tiles first. */
    static List<TileRect> tiles(int width, int height, int size) {
        int rows = (height + size - 1) / size;
        int tail = Math.max(MIN_TAIL_ROWS, (rows + TAIL_FRACTION_DIVISOR - 1) / TAIL_FRACTION_DIVISOR);
        int bands = Math.max(0, (rows - tail) / 2);
        if (bands == 0) {
            return Renderer.tiles(width, height, size);
        }
        int large = 2 * size, top = bands * large;
        List<TileRect> tiles = new ArrayList<>(Renderer.tiles(width, top, large));
        for (TileRect tile : Renderer.tiles(width, height - top, size)) {
            tiles.add(new TileRect(tile.x(), top + tile.y(), tile.width(), tile.height()));
        }
        return tiles;
    }
}

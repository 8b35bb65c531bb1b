package studio.server.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import studio.engine.render.TileRect;

/**
 * A cluster job's tiling: every pixel in exactly one tile, the large tiles queued first, and the
 * job's last rows in small tiles, so that its tail is as short as with small tiles everywhere.
 */
class ClusterTilingTest {

    @ParameterizedTest
    @CsvSource({"960,720,64", "3840,2160,64", "150,330,64", "160,120,32", "128,128,6", "64,64,64", "1,1,64", "1000,1,64",
            "70,1000,64"})
    void everyPixelIsInExactlyOneTileAndTheLastRowsAreSmall(int width, int height, int size) {
        List<TileRect> tiles = ClusterTiling.tiles(width, height, size);
        int[] covered = new int[width * height];
        for (TileRect tile : tiles) {
            assertThat(tile.width()).isBetween(1, 2 * size);
            assertThat(tile.height()).isBetween(1, 2 * size);
            for (int y = tile.y(); y < tile.y() + tile.height(); y++) {
                for (int x = tile.x(); x < tile.x() + tile.width(); x++) {
                    covered[y * width + x]++;
                }
            }
        }
        assertThat(covered).containsOnly(1);
        int rows = (height + size - 1) / size;
        int tailRows = Math.min(rows, Math.max(ClusterTiling.MIN_TAIL_ROWS,
                (rows + ClusterTiling.TAIL_FRACTION_DIVISOR - 1) / ClusterTiling.TAIL_FRACTION_DIVISOR));
        int tailTop = (rows - tailRows) * size;
        boolean small = false;
        for (TileRect tile : tiles) {
            boolean isSmall = tile.width() <= size && tile.height() <= size;
            assertThat(!small || isSmall).as("a large tile after a small one: %s", tile).isTrue();
            small |= isSmall;
            if (tile.y() + tile.height() > tailTop) {
                assertThat(isSmall).as("a tile of the last %d rows: %s", tailRows, tile).isTrue();
            }
        }
    }

    @Test
    void aLargeImageTakesAboutHalfTheTiles() {
        assertThat(ClusterTiling.tiles(960, 720, 64)).hasSize(4 * 8 + 4 * 15);
        assertThat(ClusterTiling.tiles(128, 128, ClusterWarmUp.TILE_SIZE)).hasSize(253);
    }

    /**
     * Builds that cut every job into uniform tiles queued tasks and kept results and claims under
     * these names. A member of such a build in the same cluster (a rolling restart onto this one)
     * must never take this build's tasks nor read its results: it would render or place tile n as its
     * own tiling's rectangle n, some of them of the right size in the wrong place.
     */
    @Test
    void membersOfTheUniformTilingShareNoTileWithThisOne() {
        assertThat(ClusterMaps.TILE_QUEUE).isNotEqualTo("studio-tile-queue");
        assertThat(ClusterMaps.tiles("j1")).isNotEqualTo("studio-tiles-j1").startsWith("studio-tiles-");
        assertThat(ClusterMaps.claims("j1")).isNotEqualTo("studio-claims-j1").startsWith("studio-claims-");
    }
}

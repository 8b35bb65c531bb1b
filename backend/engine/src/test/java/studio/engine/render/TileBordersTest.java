package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

/** The edge pixels neighbouring tiles share: one tile traces each, the other waits for it, and nobody waits forever. */
class TileBordersTest {

    /** 64 x 64 in 32-pixel tiles: pixel (31, 0) is on the right edge of the first tile, in the second's ring. */
    private final TileBorders borders = new TileBorders(64, 64, 32);
    private final int entry = borders.entryOf(31, 0);
    private final StopSignal stop = new StopSignal();

    /**
     * A tile reads a ring of two pixels (its pixels' neighbours' neighbourhoods): every pixel within
     * two of an edge between tiles has an entry of its own, on a 70 x 50 image whose last tiles are narrow.
     */
    @Test
    void everyPixelWithinTwoOfATilesEdgeHasAnEntryOfItsOwn() {
        TileBorders narrow = new TileBorders(70, 50, 32);
        java.util.Set<Integer> seen = new java.util.HashSet<>();
        for (int y = 0; y < 50; y++) {
            for (int x = 0; x < 70; x++) {
                int e = narrow.entryOf(x, y);
                boolean nearEdge = near(x, 70) || near(y, 50);
                if (nearEdge) {
                    assertTrue(e >= 0, "pixel " + x + "," + y);
                    assertTrue(seen.add(e), "pixel " + x + "," + y + " shares entry " + e);
                }
            }
        }
    }

    /** Within two of a border between tiles of 32 along an extent. */
    private static boolean near(int c, int extent) {
        for (int edge = 32; edge < extent; edge += 32) {
            if (c >= edge - TileBorders.LINES && c < edge + TileBorders.LINES) {
                return true;
            }
        }
        return false;
    }

    @Test
    void holdsAtMost22BytesAPixelWith32PixelTiles() {
        // the figure the server's render memory estimate counts (RenderMemory.BYTES_PER_PIXEL)
        long bytes = new TileBorders(1024, 768, 32).bytes();
        assertTrue(bytes <= 22L * 1024 * 768, bytes / (1024.0 * 768) + " bytes a pixel");
        assertTrue(bytes > 20L * 1024 * 768, bytes / (1024.0 * 768) + " bytes a pixel: update the estimate's figure");
    }

    @Test
    void theSecondTileReadsWhatTheFirstStored() {
        assertEquals(-1, borders.loadOrClaim(entry, new double[3], new double[3], new double[3], 0, stop));
        borders.store(entry, new double[] {1, 2, 3}, new double[] {0.1, 0.2, 0.3}, new double[] {4, 5, 6}, 0, 2, 0.25);

        double[] sum = new double[3], min = new double[3], max = new double[3];
        assertEquals(2, borders.loadOrClaim(entry, sum, min, max, 0, stop));
        assertArrayEquals(new double[] {1, 2, 3}, sum);
        assertArrayEquals(new double[] {0.1, 0.2, 0.3}, min);
        assertArrayEquals(new double[] {4, 5, 6}, max);
        assertEquals(0.25, borders.penumbraLight(entry));
    }

    @Test
    void aWaitingTileTakesOverAPixelTheOtherGaveUp() throws Exception {
        borders.loadOrClaim(entry, new double[3], new double[3], new double[3], 0, stop);
        CompletableFuture<Integer> waiting = CompletableFuture.supplyAsync(
                () -> borders.loadOrClaim(entry, new double[3], new double[3], new double[3], 0, stop));

        borders.abandon(entry);

        assertEquals(-1, waiting.get(10, TimeUnit.SECONDS), "the waiting tile owns the pixel now");
    }

    /**
     * A tile that claimed an edge pixel and was then stopped (or failed) may never store it; the
     * tile waiting for it stops waiting once the render stops, whatever the other did.
     */
    @Test
    void aWaitingTileStopsWaitingWhenTheRenderStops() throws Exception {
        borders.loadOrClaim(entry, new double[3], new double[3], new double[3], 0, stop);
        CompletableFuture<Integer> waiting = CompletableFuture.supplyAsync(
                () -> borders.loadOrClaim(entry, new double[3], new double[3], new double[3], 0, stop));

        stop.raise();

        ExecutionException e = assertThrows(ExecutionException.class, () -> waiting.get(10, TimeUnit.SECONDS));
        assertInstanceOf(RenderCancelledException.class, e.getCause());
        assertTrue(waiting.isCompletedExceptionally());
    }
}

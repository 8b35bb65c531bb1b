package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;

import studio.engine.sampler.JitteredSampler;
import studio.engine.scene.Scene;

class RendererTest {

    /** 100 x 70 cuts into 4 x 3 tiles of 32, the last column and row partial. */
    private static final int WIDTH = 100, HEIGHT = 70;
    /** 12 tiles of 32 would be fewer than 16 per thread, so the tiles are 16 pixels: 7 x 5. */
    private static final int TILES = 35;
    private static final Scene SCENE = MixedScene.SCENE;
    private static final RenderSettings SETTINGS = new RenderSettings(WIDTH, HEIGHT, new JitteredSampler(4), 6, 1,
            42L, RenderSettings.DEFAULT_MIN_PATH_WEIGHT);

    @Test
    void oneAndTwoThreadsGiveBitIdenticalFilms() {
        RenderResult single = Renderer.render(RenderRequest.of(SCENE, SETTINGS));
        RenderResult multi = Renderer.render(RenderRequest.of(SCENE, SETTINGS.withThreads(2)));
        RenderResult again = Renderer.render(RenderRequest.of(SCENE, SETTINGS.withThreads(3)));

        assertEquals(0, single.nonFiniteSamples());
        assertBitIdentical(single.film(), multi.film());
        assertBitIdentical(single.film(), again.film());
        assertEquals(single.raysTraced(), multi.raysTraced());
        assertTrue(single.raysTraced() > 4L * WIDTH * HEIGHT, "rays: " + single.raysTraced());
    }

    /** The render's CPU time is its threads' own: some, and at most what its threads could spend in its wall time. */
    @Test
    void cpuTimeIsTheRenderThreadsOwn() {
        for (int threads : new int[] {1, 2}) {
            RenderResult result = Renderer.render(RenderRequest.of(SCENE, SETTINGS.withThreads(threads)));
            assertTrue(result.cpuNanos() > 0, "cpu " + result.cpuNanos());
            // thread clocks tick a little coarser than the wall clock: a millisecond of slack per thread
            assertTrue(result.cpuNanos() <= threads * (result.elapsedNanos() + 1_000_000L),
                    threads + " threads: cpu " + result.cpuNanos() + " ns in " + result.elapsedNanos() + " ns");
        }
    }

    @Test
    void anotherSeedGivesAnotherJitteredImage() {
        Film a = Renderer.render(RenderRequest.of(SCENE, SETTINGS)).film();
        Film b = Renderer.render(RenderRequest.of(SCENE, new RenderSettings(WIDTH, HEIGHT, new JitteredSampler(4), 6, 1, 43L,
                RenderSettings.DEFAULT_MIN_PATH_WEIGHT))).film();

        int differing = 0;
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                differing += a.get(x, y, 0) != b.get(x, y, 0) ? 1 : 0;
            }
        }
        assertTrue(differing > 100, "pixels that changed with the seed: " + differing);
    }

    @Test
    void cancellingAfterTheFirstTileThrowsRenderCancelled() {
        for (int threads : new int[] {1, 2}) {
            AtomicBoolean cancelled = new AtomicBoolean();
            AtomicInteger finished = new AtomicInteger();
            RenderListener listener = (film, tile, done, total) -> {
                finished.incrementAndGet();
                cancelled.set(true);
            };

            assertThrows(RenderCancelledException.class,
                    () -> Renderer.render(RenderRequest.of(SCENE, SETTINGS.withThreads(threads)).heardBy(listener).cancelledWhen(cancelled::get)));

            assertTrue(finished.get() >= 1 && finished.get() < TILES, threads + " threads finished " + finished);
        }
    }

    @Test
    void cancelledBeforeStartingRendersNoTile() {
        AtomicInteger finished = new AtomicInteger();

        assertThrows(RenderCancelledException.class, () -> Renderer.render(RenderRequest.of(SCENE, SETTINGS.withThreads(2)).heardBy((film, tile, done, total) -> finished.incrementAndGet()).cancelledWhen(() -> true)));

        assertEquals(0, finished.get());
    }

    /** What a listener heard about one tile, with the tile's pixels as they were at that moment. */
    private record Report(TileRect tile, int done, int total, double[] pixels) {
    }

    @Test
    void smallImagesGetSmallerTilesSoThatEveryThreadHasEnoughOfThem() {
        assertEquals(RenderSettings.TILE_SIZE, Renderer.tileSize(800, 600, 2));
        assertEquals(RenderSettings.TILE_SIZE, Renderer.tileSize(256, 256, 2));
        assertEquals(RenderSettings.TILE_SIZE / 2, Renderer.tileSize(160, 120, 2));
        assertEquals(RenderSettings.TILE_SIZE / 2, Renderer.tileSize(800, 600, 32));
        assertEquals(RenderSettings.TILE_SIZE / 2, Renderer.tileSize(1, 1, 1));
    }

    @Test
    void progressReportsEveryTileOnceWithDoneCountingOneToTotal() {
        List<Report> reports = Collections.synchronizedList(new ArrayList<>());
        RenderListener listener = (film, tile, done, total) -> reports.add(new Report(tile, done, total,
                snapshot(film, tile)));

        RenderResult result = Renderer.render(RenderRequest.of(SCENE, SETTINGS.withThreads(2)).heardBy(listener));

        assertEquals(TILES, reports.size());
        List<Integer> dones = new ArrayList<>();
        int[][] covered = new int[HEIGHT][WIDTH];
        for (Report report : reports) {
            dones.add(report.done());
            assertEquals(TILES, report.total());
            TileRect tile = report.tile();
            assertTrue(tile.width() <= RenderSettings.TILE_SIZE && tile.height() <= RenderSettings.TILE_SIZE);
            for (int y = tile.y(); y < tile.y() + tile.height(); y++) {
                for (int x = tile.x(); x < tile.x() + tile.width(); x++) {
                    covered[y][x]++;
                }
            }
            assertArrayEquals(snapshot(result.film(), tile), report.pixels(),
                    "a tile's pixels are final when it is reported: " + tile);
        }
        Collections.sort(dones);
        for (int i = 0; i < TILES; i++) {
            assertEquals(i + 1, dones.get(i));
        }
        for (int[] row : covered) {
            for (int count : row) {
                assertEquals(1, count, "every pixel is in exactly one reported tile");
            }
        }
    }

    @Test
    void tilesCoverTheImageRowByRowWithPartialTilesAtTheEdges() {
        List<TileRect> tiles = Renderer.tiles(WIDTH, HEIGHT, 32);

        assertEquals(12, tiles.size());
        assertEquals(new TileRect(0, 0, 32, 32), tiles.get(0));
        assertEquals(new TileRect(96, 0, 4, 32), tiles.get(3));
        assertEquals(new TileRect(96, 64, 4, 6), tiles.get(11));
        assertEquals(List.of(new TileRect(0, 0, 1, 1)), Renderer.tiles(1, 1, 32));
    }

    @Test
    void renderSettingsRejectInvalidValues() {
        JitteredSampler sampler = new JitteredSampler(1);
        assertThrows(IllegalArgumentException.class, () -> new RenderSettings(0, 10, sampler, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> new RenderSettings(10, -1, sampler, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> new RenderSettings(10, 10, null, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> new RenderSettings(10, 10, sampler, -1, 1));
        assertThrows(IllegalArgumentException.class, () -> new RenderSettings(10, 10, sampler, 1, -2));
        assertThrows(IllegalArgumentException.class,
                () -> new RenderSettings(10, 10, sampler, 1, 1, 0L, Double.NaN));
    }

    @Test
    void filmRejectsNonFiniteValuesAndStoresBlackInstead() {
        Film film = new Film(2, 1);

        assertTrue(film.set(0, 0, 0.25, 0.5, 0.75));
        assertFalse(film.set(1, 0, 0.5, Double.NaN, 0.5));
        assertFalse(film.set(0, 0, Double.POSITIVE_INFINITY, 0, 0));

        for (int c = 0; c < 3; c++) {
            assertEquals(0, film.get(0, 0, c), 0.0);
            assertEquals(0, film.get(1, 0, c), 0.0);
        }
    }

    private static double[] snapshot(Film film, TileRect tile) {
        double[] values = new double[3 * tile.width() * tile.height()];
        int i = 0;
        for (int y = tile.y(); y < tile.y() + tile.height(); y++) {
            for (int x = tile.x(); x < tile.x() + tile.width(); x++) {
                for (int c = 0; c < 3; c++) {
                    values[i++] = film.get(x, y, c);
                }
            }
        }
        return values;
    }

    private static void assertBitIdentical(Film expected, Film actual) {
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(Double.doubleToRawLongBits(expected.get(x, y, c)),
                            Double.doubleToRawLongBits(actual.get(x, y, c)), "pixel " + x + "," + y + " channel " + c);
                }
            }
        }
    }
}

package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class FilmTest {

    /** Pixel (x, y)'s channel c holds 100x + 10y + c, so every value says where it came from. */
    private static void fill(Film film, TileRect area) {
        for (int y = area.y(); y < area.y() + area.height(); y++) {
            for (int x = area.x(); x < area.x() + area.width(); x++) {
                film.set(x, y, 100 * x + 10 * y, 100 * x + 10 * y + 1, 100 * x + 10 * y + 2);
            }
        }
    }

    private static double[] expected(TileRect tile) {
        double[] out = new double[3 * tile.width() * tile.height()];
        int i = 0;
        for (int y = tile.y(); y < tile.y() + tile.height(); y++) {
            for (int x = tile.x(); x < tile.x() + tile.width(); x++) {
                for (int c = 0; c < 3; c++) {
                    out[i++] = 100 * x + 10 * y + c;
                }
            }
        }
        return out;
    }

    @Test
    void aTileFilmGivesItsPixelsRowMajorInImageCoordinates() {
        TileRect tile = new TileRect(7, 5, 4, 3);
        Film film = Film.ofTile(tile);
        fill(film, tile);

        assertArrayEquals(expected(tile), film.pixels(tile));
    }

    @Test
    void aTileOfAWholeImageIsCutOutRowByRow() {
        Film film = new Film(9, 8);
        fill(film, new TileRect(0, 0, 9, 8));
        TileRect tile = new TileRect(2, 3, 5, 4);

        assertArrayEquals(expected(tile), film.pixels(tile));
    }

    @Test
    void thePixelsAreACopy() {
        TileRect tile = new TileRect(0, 0, 2, 2);
        Film film = Film.ofTile(tile);
        fill(film, tile);
        double[] pixels = film.pixels(tile);
        pixels[0] = -1;

        assertEquals(0, film.get(0, 0, 0));
    }

    @Test
    void aNonFiniteValueIsStoredAsBlack() {
        Film film = new Film(1, 1);

        assertFalse(film.set(0, 0, Double.NaN, 1, 1));
        assertArrayEquals(new double[] {0, 0, 0}, film.pixels(new TileRect(0, 0, 1, 1)));
    }

    @Test
    void setPixelsStoresWhatPixelsGivesInTheSamePlaces() {
        Film source = new Film(9, 8);
        fill(source, new TileRect(0, 0, 9, 8));
        TileRect tile = new TileRect(2, 3, 5, 4);
        Film target = Film.ofTile(tile);

        target.setPixels(tile, source.pixels(tile));
        assertArrayEquals(expected(tile), target.pixels(tile));
    }

    @Test
    void setPixelsStoresANonFinitePixelAsBlack() {
        TileRect tile = new TileRect(0, 0, 2, 1);
        Film film = Film.ofTile(tile);

        film.setPixels(tile, new double[] {1, 2, 3, 4, Double.POSITIVE_INFINITY, 6});
        assertArrayEquals(new double[] {1, 2, 3, 0, 0, 0}, film.pixels(tile));
    }

    @Test
    void setPixelsRefusesTheWrongNumberOfValues() {
        TileRect tile = new TileRect(0, 0, 2, 2);
        Film film = Film.ofTile(tile);

        assertThrows(IllegalArgumentException.class, () -> film.setPixels(tile, new double[11]));
    }
}

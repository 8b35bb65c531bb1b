package studio.server.job;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.util.Base64;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;

import studio.engine.image.ImageEncoder;
import studio.engine.render.Film;
import studio.engine.render.TileRect;

/** A tile event's PNG holds exactly the tile's pixels, as the whole image would show them. */
class RenderJobTileTest {

    @Test
    void aTilePngDecodesToTheTilesPixels() throws IOException {
        Film film = new Film(40, 30);
        for (int y = 0; y < 30; y++) {
            for (int x = 0; x < 40; x++) {
                film.set(x, y, x / 40.0, y / 30.0, (x * y % 7) / 7.0);
            }
        }
        TileRect tile = new TileRect(8, 4, 32, 26);

        BufferedImage png = ImageIO.read(new ByteArrayInputStream(Base64.getDecoder().decode(TilePng.encode(film, tile))));

        BufferedImage whole = ImageEncoder.toImage(film);
        assertThat(png.getWidth()).isEqualTo(32);
        assertThat(png.getHeight()).isEqualTo(26);
        for (int y = 0; y < 26; y++) {
            for (int x = 0; x < 32; x++) {
                assertThat(png.getRGB(x, y)).as("(%d, %d)", x, y).isEqualTo(whole.getRGB(8 + x, 4 + y));
            }
        }
    }
}

package studio.engine.image;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;

import studio.engine.math.Srgb;
import studio.engine.render.Film;
import studio.engine.render.PixelLattice;

class ImageEncoderTest {

    @Test
    void pngRoundTripKeepsSizeAndTheSrgbEncodedColours() throws IOException {
        // linear 0.5 -> sRGB 0.7354 -> 188; 0.18 -> 0.4614 -> 118; 0.001 -> 12.92 * 0.001 -> 3; >= 1 clamps to 255
        Film film = new Film(3, 2);
        film.set(0, 0, 0.5, 0.5, 0.5);
        film.set(1, 0, 0, 1, 0.18);
        film.set(2, 0, 0.001, 2.5, -1);
        film.set(0, 1, 1, 0, 0);

        BufferedImage image = read(png(film));

        assertEquals(3, image.getWidth());
        assertEquals(2, image.getHeight());
        assertRgb(188, 188, 188, image.getRGB(0, 0));
        assertRgb(0, 255, 118, image.getRGB(1, 0));
        assertRgb(3, 255, 0, image.getRGB(2, 0));
        assertRgb(255, 0, 0, image.getRGB(0, 1));
        assertRgb(0, 0, 0, image.getRGB(1, 1));
    }

    @Test
    void aLatticesImageHoldsTheFilmsPixelsOnItOnly() {
        Film film = new Film(10, 7);
        for (int y = 0; y < 7; y++) {
            for (int x = 0; x < 10; x++) {
                film.set(x, y, x / 10.0, y / 10.0, 1);
            }
        }

        BufferedImage image = ImageEncoder.toImage(film, new PixelLattice(4, 2));

        assertEquals(2, image.getWidth(), "columns 2 and 6");
        assertEquals(2, image.getHeight(), "rows 2 and 6");
        for (int j = 0; j < 2; j++) {
            for (int i = 0; i < 2; i++) {
                int x = 2 + 4 * i, y = 2 + 4 * j;
                assertRgb(Srgb.toByte(x / 10.0), Srgb.toByte(y / 10.0), 255, image.getRGB(i, j));
            }
        }
        BufferedImage whole = ImageEncoder.toImage(film, PixelLattice.ALL);
        assertEquals(10, whole.getWidth());
        assertRgb(Srgb.toByte(0.9), Srgb.toByte(0.6), 255, whole.getRGB(9, 6));
    }

    @Test
    void aLatticesJpegImageHoldsTheSamePixelsAndWritesTheSameFile() throws IOException {
        // a film large enough to be converted by several threads, with colours that differ in each channel
        Film film = new Film(700, 400);
        java.util.Random random = new java.util.Random(3);
        for (int y = 0; y < 400; y++) {
            for (int x = 0; x < 700; x++) {
                film.set(x, y, random.nextDouble(), x / 700.0, y / 300.0);
            }
        }
        for (PixelLattice lattice : new PixelLattice[] {PixelLattice.ALL, new PixelLattice(8, 4), new PixelLattice(2, 0)}) {
            BufferedImage packed = ImageEncoder.toImage(film, lattice), bytes = ImageEncoder.toJpegImage(film, lattice);

            assertEquals(packed.getWidth(), bytes.getWidth());
            assertEquals(packed.getHeight(), bytes.getHeight());
            for (int y = 0; y < packed.getHeight(); y++) {
                for (int x = 0; x < packed.getWidth(); x++) {
                    assertEquals(packed.getRGB(x, y), bytes.getRGB(x, y), lattice + " pixel " + x + "," + y);
                }
            }
            ByteArrayOutputStream fromPacked = new ByteArrayOutputStream(), fromBytes = new ByteArrayOutputStream();
            ImageEncoder.writeJpeg(packed, 0.85, fromPacked);
            ImageEncoder.writeJpeg(bytes, 0.85, fromBytes);
            assertTrue(java.util.Arrays.equals(fromPacked.toByteArray(), fromBytes.toByteArray()), lattice + ": the same file");
        }
    }

    @Test
    void jpegRoundTripKeepsSizeAndApproximatelyTheColour() throws IOException {
        Film film = new Film(16, 8);
        for (int y = 0; y < 8; y++) {
            for (int x = 0; x < 16; x++) {
                film.set(x, y, 0.5, 0.5, 0.5);
            }
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream();

        ImageEncoder.writeJpeg(ImageEncoder.toImage(film), 0.95, out);
        BufferedImage image = read(out.toByteArray());

        assertEquals(16, image.getWidth());
        assertEquals(8, image.getHeight());
        byte[] bytes = out.toByteArray();
        assertTrue((bytes[0] & 0xff) == 0xff && (bytes[1] & 0xff) == 0xd8, "JPEG magic");
        for (int y = 0; y < 8; y++) {
            for (int x = 0; x < 16; x++) {
                int rgb = image.getRGB(x, y);
                for (int shift = 0; shift <= 16; shift += 8) {
                    assertEquals(188, rgb >> shift & 0xff, 2, "pixel " + x + "," + y);
                }
            }
        }
    }

    @Test
    void jpegQualityOutsideZeroToOneIsRejected() {
        BufferedImage image = ImageEncoder.toImage(new Film(1, 1));
        for (double quality : new double[] {-0.1, 1.1, Double.NaN}) {
            assertThrows(IllegalArgumentException.class,
                    () -> ImageEncoder.writeJpeg(image, quality, new ByteArrayOutputStream()), "quality " + quality);
        }
    }

    private static byte[] png(Film film) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ImageEncoder.writePng(ImageEncoder.toImage(film), out);
        byte[] bytes = out.toByteArray();
        assertTrue(bytes.length > 8 && bytes[1] == 'P' && bytes[2] == 'N' && bytes[3] == 'G', "PNG magic");
        return bytes;
    }

    private static BufferedImage read(byte[] bytes) throws IOException {
        BufferedImage image = ImageIO.read(new ByteArrayInputStream(bytes));
        assertTrue(image != null, "ImageIO reads the encoded bytes back");
        return image;
    }

    private static void assertRgb(int r, int g, int b, int argb) {
        assertEquals(r, argb >> 16 & 0xff, "red");
        assertEquals(g, argb >> 8 & 0xff, "green");
        assertEquals(b, argb & 0xff, "blue");
    }
}

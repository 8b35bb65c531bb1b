package studio.engine.image;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.Random;
import java.util.concurrent.ForkJoinPool;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;

/**
 * Our PNG encoder: every pixel read back exactly by ImageIO's decoder, across the band joins of a
 * large image, in all five filters' territory (flat areas, gradients, noise, hard edges), the same
 * bytes on any number of cores, and files no larger than ImageIO's own encoder writes.
 */
class PngEncoderTest {

    /** Flat bands, gradients both ways, noise and hard-edged squares: every filter wins somewhere. */
    private static int[] picture(int width, int height, long seed) {
        Random random = new Random(seed);
        int[] rgb = new int[width * height];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int p;
                switch ((y / 7 + x / 50) % 4) {
                    case 0 -> p = 0x336699;
                    case 1 -> p = (x * 255 / Math.max(1, width - 1)) << 16 | (y % 256) << 8 | (x + y) % 256;
                    case 2 -> p = random.nextInt(1 << 24);
                    default -> p = ((x / 3 + y / 3) % 2 == 0) ? 0xffffff : 0x000000;
                }
                rgb[y * width + x] = p;
            }
        }
        return rgb;
    }

    private static byte[] encode(int[] rgb, int width, int height) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        PngEncoder.write(rgb, width, height, out);
        return out.toByteArray();
    }

    private static void assertReadsBack(int[] rgb, int width, int height) throws IOException {
        BufferedImage image = ImageIO.read(new ByteArrayInputStream(encode(rgb, width, height)));
        assertNotNull(image, "ImageIO reads it");
        assertEquals(width, image.getWidth());
        assertEquals(height, image.getHeight());
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                assertEquals(rgb[y * width + x], image.getRGB(x, y) & 0xffffff, "pixel " + x + "," + y);
            }
        }
    }

    @Test
    void tinyAndOddSizedImagesReadBackExactly() throws IOException {
        for (int[] size : new int[][] {{1, 1}, {1, 9}, {9, 1}, {2, 3}, {101, 37}}) {
            assertReadsBack(picture(size[0], size[1], 7), size[0], size[1]);
        }
    }

    @Test
    void aLargeImageDeflatedInParallelBandsReadsBackExactly() throws IOException {
        // 1200 x 900: 3.2 MB of rows, four bands joined into one zlib stream
        assertReadsBack(picture(1200, 900, 11), 1200, 900);
    }

    @Test
    void theBytesAreTheSameOnOneCoreAsOnAll() throws Exception {
        int[] rgb = picture(1200, 900, 3);
        byte[] all = encode(rgb, 1200, 900);
        ForkJoinPool one = new ForkJoinPool(1);
        try {
            byte[] single = one.submit(() -> encode(rgb, 1200, 900)).get();
            assertArrayEquals(all, single);
        } finally {
            one.shutdown();
        }
    }

    @Test
    void filesAreNoLargerThanImageIOsOwn() throws IOException {
        // a smooth render-like image: gradients with a little noise
        int width = 640, height = 480;
        int[] rgb = new int[width * height];
        Random random = new Random(5);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int r = Math.min(255, x * 255 / width + random.nextInt(3)), g = y * 255 / height, b = (x + y) / 5 % 256;
                rgb[y * width + x] = r << 16 | g << 8 | b;
            }
        }
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, width, height, rgb, 0, width);
        ByteArrayOutputStream theirs = new ByteArrayOutputStream();
        assertTrue(ImageIO.write(image, "png", theirs));
        int ours = encode(rgb, width, height).length;
        assertTrue(ours <= theirs.size(), "ours " + ours + " bytes, ImageIO's " + theirs.size());
    }

    @Test
    void refusesAnImageWithFewerPixelsThanItsSize() {
        assertThrows(IllegalArgumentException.class, () -> encode(new int[5], 2, 3));
        assertThrows(IllegalArgumentException.class, () -> encode(new int[0], 0, 0));
    }
}

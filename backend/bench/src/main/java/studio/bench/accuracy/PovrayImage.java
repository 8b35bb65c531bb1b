package studio.bench.accuracy;

import java.awt.image.BufferedImage;
import java.awt.image.Raster;
import java.io.IOException;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import studio.engine.math.Srgb;

/**
 * POV-Ray's output read back into linear light, as our films hold it: a PNG (16 bits a channel,
 * {@code +FN16}, so that the error measured is the render's and not 8-bit rounding) whose values
 * are sRGB-encoded (the scenes say {@code assumed_gamma 1.0}; POV-Ray 3.7 writes sRGB files), decoded
 * channel by channel; optionally averaged over blocks, for a reference rendered at a multiple of the
 * size.
 */
final class PovrayImage {

    private PovrayImage() {
    }

    /**
     * The linear RGB values of the PNG, row by row, three per pixel, each the mean over a
     * {@code block x block} square of the file's pixels (1: the pixels themselves).
     */
    static double[] linear(Path png, int block) throws IOException {
        BufferedImage image = ImageIO.read(png.toFile());
        if (image == null) {
            throw new IOException("not an image: " + png);
        }
        Raster raster = image.getRaster();
        int bits = raster.getSampleModel().getSampleSize(0);
        double max = (1 << bits) - 1;
        int width = image.getWidth() / block, height = image.getHeight() / block;
        double[] out = new double[3 * width * height];
        double share = 1.0 / (block * block);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                for (int dy = 0; dy < block; dy++) {
                    for (int dx = 0; dx < block; dx++) {
                        for (int c = 0; c < 3; c++) {
                            double encoded = raster.getSample(x * block + dx, y * block + dy, c) / max;
                            out[3 * (y * width + x) + c] += Srgb.toLinear(encoded) * share;
                        }
                    }
                }
            }
        }
        return out;
    }
}

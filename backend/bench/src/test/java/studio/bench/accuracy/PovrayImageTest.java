package studio.bench.accuracy;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.awt.image.BufferedImage;
import java.awt.image.WritableRaster;
import java.io.IOException;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import studio.engine.math.Srgb;

class PovrayImageTest {

    @Test
    void readsSixteenBitSrgbIntoLinearLightAndAveragesBlocks(@TempDir Path dir) throws IOException {
        // RGB, 16 bits a channel, as POV-Ray writes with +FN16
        BufferedImage image = new BufferedImage(new java.awt.image.ComponentColorModel(
                java.awt.color.ColorSpace.getInstance(java.awt.color.ColorSpace.CS_sRGB), false, false,
                java.awt.Transparency.OPAQUE, java.awt.image.DataBuffer.TYPE_USHORT),
                java.awt.image.Raster.createInterleavedRaster(java.awt.image.DataBuffer.TYPE_USHORT, 4, 2, 3, null),
                false, null);
        WritableRaster raster = image.getRaster();
        int[] values = {0, 65535, 32768, 1000};
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 4; x++) {
                for (int c = 0; c < 3; c++) {
                    raster.setSample(x, y, c, values[(x + y + c) % 4]);
                }
            }
        }
        Path png = dir.resolve("p.png");
        ImageIO.write(image, "png", png.toFile());

        double[] linear = PovrayImage.linear(png, 1);
        assertThat(linear).hasSize(4 * 2 * 3);
        assertThat(linear[0]).isEqualTo(0);
        assertThat(linear[1]).isCloseTo(1, within(1e-12));
        assertThat(linear[2]).isCloseTo(Srgb.toLinear(32768 / 65535.0), within(1e-12));
        double[] blocks = PovrayImage.linear(png, 2);
        assertThat(blocks).hasSize(2 * 3);
        double mean = 0;
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 2; x++) {
                mean += linear[3 * (y * 4 + x)] / 4;
            }
        }
        assertThat(blocks[0]).isCloseTo(mean, within(1e-12));
    }
}

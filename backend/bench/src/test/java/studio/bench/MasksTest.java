package studio.bench;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.awt.image.BufferedImage;

import org.junit.jupiter.api.Test;

class MasksTest {

    private static BufferedImage image(int w, int h, int... rgb) {
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, w, h, rgb, 0, w);
        return image;
    }

    @Test
    void aPixelIsAnObjectFromHalfWayUpInItsBrightestChannel() {
        BufferedImage image = image(5, 1, 0x000000, 0x7f7f7f, 0x800000, 0x000080, 0xffffff);
        assertArrayEquals(new boolean[] {false, false, true, true, true}, Masks.mask(image));
    }

    @Test
    void identicalMasksAgreeEverywhere() {
        BufferedImage a = image(2, 2, 0xffffff, 0, 0, 0xffffff);
        assertEquals(1.0, Masks.agreement(a, a));
    }

    @Test
    void agreementIsTheShareOfPixelsWithTheSameMask() {
        BufferedImage a = image(2, 2, 0xffffff, 0, 0, 0xffffff);
        BufferedImage b = image(2, 2, 0xffffff, 0, 0, 0);
        assertEquals(0.75, Masks.agreement(a, b));
        assertEquals(0.0, Masks.agreement(a, image(2, 2, 0, 0xffffff, 0xffffff, 0)));
        // shading does not matter, only which side of the threshold a pixel is on
        assertEquals(1.0, Masks.agreement(a, image(2, 2, 0x90a0b0, 0x101010, 0x7f0000, 0x00ff00)));
    }

    @Test
    void imagesOfDifferentSizesDoNotAgree() {
        assertEquals(0.0, Masks.agreement(image(2, 1, 0, 0), image(1, 2, 0, 0)));
        assertThrows(IllegalArgumentException.class, () -> Masks.agreement(new boolean[2], new boolean[3]));
    }

    @Test
    void intersectionOverUnionIgnoresTheBackground() {
        boolean[] a = {true, true, false, false, false, false, false, false};
        boolean[] b = {true, false, true, false, false, false, false, false};
        assertEquals(1.0 / 3, Masks.intersectionOverUnion(a, b), 1e-12);
        assertEquals(0.75, Masks.agreement(a, b));
        assertEquals(1.0, Masks.intersectionOverUnion(new boolean[3], new boolean[3]));
    }

    @Test
    void coverageCountsObjectPixels() {
        assertEquals(0.25, Masks.coverage(new boolean[] {true, false, false, false}));
    }

    @Test
    void meanAbsoluteDifferenceIsPerChannelInLevels() {
        BufferedImage a = image(1, 1, 0x102030);
        BufferedImage b = image(1, 1, 0x132030);
        assertEquals(1.0, Masks.meanAbsoluteDifference(a, b), 1e-12);
        assertEquals(0.0, Masks.meanAbsoluteDifference(a, a));
    }
}

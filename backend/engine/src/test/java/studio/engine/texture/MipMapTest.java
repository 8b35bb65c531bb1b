package studio.engine.texture;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

import studio.engine.math.Srgb;
import studio.engine.memory.MemoryGate;

/** The pyramid: decoded to linear light once, each level the mean of the one below, trilinear between them. */
class MipMapTest {

    private static final int GREY = 0x808080, WHITE = 0xffffff;

    @Test
    void decodesSrgbToLinearAndHalvesToTheMean() {
        int[] pixels = {GREY, WHITE, WHITE, GREY, GREY, WHITE, WHITE, GREY}; // 4 x 2
        MipMap map = MipMap.fromSrgb(4, 2, pixels, MemoryGate.UNLIMITED);
        double[] out = new double[3];
        double grey = Srgb.toLinear(128 / 255.0);
        map.sample(0.125, 0.75, 0, out); // the centre of the top-left texel
        assertEquals(grey, out[0], 1e-6);
        map.sample(0.3, 0.6, 1e6, out); // a footprint of the whole image: the one-texel mean
        assertEquals((grey + 1) / 2, out[1], 1e-6);
    }

    @Test
    void repeatsBeyondTheUnitSquare() {
        int[] pixels = {GREY, WHITE, WHITE, GREY};
        MipMap map = MipMap.fromSrgb(2, 2, pixels, MemoryGate.UNLIMITED);
        double[] a = new double[3], b = new double[3];
        map.sample(0.25, 0.75, 0, a);
        map.sample(-2.75, 5.75, 0, b);
        assertEquals(a[0], b[0], 1e-12);
    }

    @Test
    void reservesItsBytesFirst() {
        long[] asked = new long[1];
        MipMap map = MipMap.fromSrgb(16, 8, new int[128], bytes -> asked[0] += bytes);
        assertEquals(map.bytes(), asked[0]);
    }
}

package studio.engine.texture;

import studio.engine.math.Srgb;
import studio.engine.memory.MemoryGate;

/**
 * An image in linear light as a pyramid of ever halved copies (a mip-map, Williams 1983), for
 * trilinear filtering: two bilinear lookups in the two levels whose texels are nearest the
 * footprint's size, blended. Decoded from sRGB once, when made; then only read, by every worker
 * thread at once. Rows run top to bottom, as image files store them; texture v runs up.
 */
public final class MipMap {

    /** Bytes a source pixel takes across the levels: 3 floats, times 4/3 for the pyramid. */
    public static final long BYTES_PER_PIXEL = 16;

    private final int[] widths, heights;
    /** Per level, 3 floats (linear r, g, b) per texel, row by row from the top. */
    private final float[][] levels;

    private MipMap(int[] widths, int[] heights, float[][] levels) {
        this.widths = widths;
        this.heights = heights;
        this.levels = levels;
    }

    /**
     * The pyramid of an sRGB image given as packed 0xRRGGBB pixels (alpha, the top byte, ignored),
     * row by row from the top; the memory it keeps is asked of {@code memory} first.
     */
    public static MipMap fromSrgb(int width, int height, int[] rgb, MemoryGate memory) {
        if (width < 1 || height < 1 || rgb == null || (long) width * height != rgb.length) {
            throw new IllegalArgumentException("an image needs width x height pixels: " + width + " x " + height);
        }
        memory.reserve(BYTES_PER_PIXEL * width * height);
        float[] decode = new float[256];
        for (int i = 0; i < 256; i++) {
            decode[i] = (float) Srgb.toLinear(i / 255.0);
        }
        int count = 1;
        for (int w = width, h = height; w > 1 || h > 1; w = Math.max(1, w / 2), h = Math.max(1, h / 2)) {
            count++;
        }
        int[] widths = new int[count], heights = new int[count];
        float[][] levels = new float[count][];
        float[] base = new float[3 * rgb.length];
        for (int i = 0; i < rgb.length; i++) {
            int p = rgb[i];
            base[3 * i] = decode[(p >> 16) & 0xff];
            base[3 * i + 1] = decode[(p >> 8) & 0xff];
            base[3 * i + 2] = decode[p & 0xff];
        }
        widths[0] = width;
        heights[0] = height;
        levels[0] = base;
        for (int l = 1; l < count; l++) {
            levels[l] = halved(levels[l - 1], widths[l - 1], heights[l - 1]);
            widths[l] = Math.max(1, widths[l - 1] / 2);
            heights[l] = Math.max(1, heights[l - 1] / 2);
        }
        return new MipMap(widths, heights, levels);
    }

    /** The level below: each texel the mean of the 2 x 2 (at an odd edge, 3) texels it covers. */
    private static float[] halved(float[] from, int w, int h) {
        int nw = Math.max(1, w / 2), nh = Math.max(1, h / 2);
        float[] to = new float[3 * nw * nh];
        for (int y = 0; y < nh; y++) {
            int y0 = 2 * y, y1 = Math.min(h - 1, 2 * y + 1), y2 = y == nh - 1 && h > 2 * nh ? h - 1 : y1;
            for (int x = 0; x < nw; x++) {
                int x0 = 2 * x, x1 = Math.min(w - 1, 2 * x + 1), x2 = x == nw - 1 && w > 2 * nw ? w - 1 : x1;
                for (int c = 0; c < 3; c++) {
                    double sum = 0;
                    int n = 0;
                    for (int yy = y0; yy <= y2; yy++) {
                        for (int xx = x0; xx <= x2; xx++) {
                            sum += from[3 * (yy * w + xx) + c];
                            n++;
                        }
                    }
                    to[3 * (y * nw + x) + c] = (float) (sum / n);
                }
            }
        }
        return to;
    }

    public int width() {
        return widths[0];
    }

    public int height() {
        return heights[0];
    }

    /** Bytes the pyramid keeps (as {@link #fromSrgb} reserved them). */
    public long bytes() {
        return BYTES_PER_PIXEL * widths[0] * heights[0];
    }

    /**
     * Into {@code out[0..2]}: the image around (s, t) (repeating; one image per unit, t up) filtered to
     * a footprint {@code texels} level-0 texels wide: trilinear, a footprint under a texel is bilinear
     * in the full image, one of the whole image (or not finite) is the one-texel mean.
     */
    public void sample(double s, double t, double texels, double[] out) {
        int last = levels.length - 1;
        double level = texels > 1 ? Math.log(texels) * (1 / Math.log(2)) : 0;
        if (!(level < last)) {
            bilinear(last, s, t, out, 0, 1);
            return;
        }
        int l0 = (int) level;
        double f = level - l0;
        bilinear(l0, s, t, out, 0, 1 - f);
        if (f > 0) {
            bilinear(l0 + 1, s, t, out, 1, f);
        }
    }

    /** Adds weight x the bilinear lookup in a level to out (first set: out is overwritten). */
    private void bilinear(int level, double s, double t, double[] out, int add, double weight) {
        int w = widths[level], h = heights[level];
        float[] texels = levels[level];
        double x = (s - Math.floor(s)) * w - 0.5, y = (1 - (t - Math.floor(t))) * h - 0.5;
        double fx = Math.floor(x), fy = Math.floor(y);
        double ax = x - fx, ay = y - fy;
        int x0 = wrap((long) fx, w), x1 = wrap((long) fx + 1, w), y0 = wrap((long) fy, h), y1 = wrap((long) fy + 1, h);
        int i00 = 3 * (y0 * w + x0), i10 = 3 * (y0 * w + x1), i01 = 3 * (y1 * w + x0), i11 = 3 * (y1 * w + x1);
        double w00 = (1 - ax) * (1 - ay) * weight, w10 = ax * (1 - ay) * weight;
        double w01 = (1 - ax) * ay * weight, w11 = ax * ay * weight;
        for (int c = 0; c < 3; c++) {
            double v = w00 * texels[i00 + c] + w10 * texels[i10 + c] + w01 * texels[i01 + c] + w11 * texels[i11 + c];
            out[c] = add == 0 ? v : out[c] + v;
        }
    }

    private static int wrap(long i, int n) {
        int r = (int) Math.floorMod(i, (long) n);
        return r;
    }
}

package studio.bench;

import java.awt.image.BufferedImage;

/**
 * Silhouette masks and how well two agree. A mask render draws every object flat white on black
 * without lights, so a pixel is "object" when its brightest channel is at least half way up
 * ({@value #THRESHOLD} of 255); two renders show the same scene when their masks agree almost
 * everywhere (the benchmark asks for {@value #REQUIRED} of the pixels).
 */
public final class Masks {

    /** The 8-bit level from which a pixel counts as part of an object. */
    public static final int THRESHOLD = 128;
    /** The agreement the benchmark requires before it compares times. */
    public static final double REQUIRED = 0.99;

    private Masks() {
    }

    /** The mask of an image: true where an object is. */
    public static boolean[] mask(BufferedImage image) {
        int w = image.getWidth(), h = image.getHeight();
        boolean[] mask = new boolean[w * h];
        int[] row = new int[w];
        for (int y = 0; y < h; y++) {
            image.getRGB(0, y, w, 1, row, 0, w);
            for (int x = 0; x < w; x++) {
                int p = row[x];
                int max = Math.max(p >> 16 & 0xff, Math.max(p >> 8 & 0xff, p & 0xff));
                mask[y * w + x] = max >= THRESHOLD;
            }
        }
        return mask;
    }

    /** The fraction of pixels on which two masks of the same size agree, in [0, 1]. */
    public static double agreement(boolean[] a, boolean[] b) {
        if (a.length != b.length) {
            throw new IllegalArgumentException("masks of different sizes: " + a.length + " and " + b.length);
        }
        if (a.length == 0) {
            return 1;
        }
        int same = 0;
        for (int i = 0; i < a.length; i++) {
            if (a[i] == b[i]) {
                same++;
            }
        }
        return (double) same / a.length;
    }

    /** The agreement of two images' masks; images of different sizes do not agree at all. */
    public static double agreement(BufferedImage a, BufferedImage b) {
        if (a.getWidth() != b.getWidth() || a.getHeight() != b.getHeight()) {
            return 0;
        }
        return agreement(mask(a), mask(b));
    }

    /**
     * Object pixels in both masks over object pixels in either (1 when neither has any): unlike
     * {@link #agreement}, it does not grow with the background, so it shows how well small objects agree.
     */
    public static double intersectionOverUnion(boolean[] a, boolean[] b) {
        if (a.length != b.length) {
            throw new IllegalArgumentException("masks of different sizes: " + a.length + " and " + b.length);
        }
        int both = 0, either = 0;
        for (int i = 0; i < a.length; i++) {
            if (a[i] && b[i]) {
                both++;
            }
            if (a[i] || b[i]) {
                either++;
            }
        }
        return either == 0 ? 1 : (double) both / either;
    }

    /** The fraction of pixels that are objects. */
    public static double coverage(boolean[] mask) {
        int on = 0;
        for (boolean m : mask) {
            if (m) {
                on++;
            }
        }
        return mask.length == 0 ? 0 : (double) on / mask.length;
    }

    /**
     * The mean absolute difference of two images of the same size, in 8-bit levels per channel (sRGB
     * as written): how far apart the shading is, for the report; -1 if the sizes differ.
     */
    public static double meanAbsoluteDifference(BufferedImage a, BufferedImage b) {
        int w = a.getWidth(), h = a.getHeight();
        if (w != b.getWidth() || h != b.getHeight()) {
            return -1;
        }
        long sum = 0;
        int[] ra = new int[w], rb = new int[w];
        for (int y = 0; y < h; y++) {
            a.getRGB(0, y, w, 1, ra, 0, w);
            b.getRGB(0, y, w, 1, rb, 0, w);
            for (int x = 0; x < w; x++) {
                for (int shift = 0; shift <= 16; shift += 8) {
                    sum += Math.abs((ra[x] >> shift & 0xff) - (rb[x] >> shift & 0xff));
                }
            }
        }
        return (double) sum / (3.0 * w * h);
    }
}

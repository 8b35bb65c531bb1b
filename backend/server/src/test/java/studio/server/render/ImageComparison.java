package studio.server.render;

import java.awt.image.BufferedImage;

/**
 * How far apart two 8-bit sRGB images are: PSNR over all channels, and the fraction of pixels
 * with a channel more than {@link #OUTLIER_LEVELS} code values off (a few flipped edge pixels are
 * expected when geometry is transformed; a wrong shadow or colour is not).
 */
public record ImageComparison(double psnr, double outlierFraction, BufferedImage diff) {

    public static final int OUTLIER_LEVELS = 24;

    public static ImageComparison of(BufferedImage expected, BufferedImage actual) {
        if (expected.getWidth() != actual.getWidth() || expected.getHeight() != actual.getHeight()) {
            throw new IllegalArgumentException("sizes differ: " + expected.getWidth() + "x" + expected.getHeight()
                    + " and " + actual.getWidth() + "x" + actual.getHeight());
        }
        int w = expected.getWidth(), h = expected.getHeight();
        BufferedImage diff = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        double squared = 0;
        long outliers = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int a = expected.getRGB(x, y), b = actual.getRGB(x, y);
                int worst = 0;
                for (int shift = 0; shift <= 16; shift += 8) {
                    int d = Math.abs((a >> shift & 0xff) - (b >> shift & 0xff));
                    squared += (double) d * d;
                    worst = Math.max(worst, d);
                }
                if (worst > OUTLIER_LEVELS) {
                    outliers++;
                }
                int v = Math.min(255, worst * 8);
                diff.setRGB(x, y, v << 16 | v << 8 | v);
            }
        }
        double mse = squared / (3.0 * w * h);
        double psnr = mse == 0 ? Double.POSITIVE_INFINITY : 10 * Math.log10(255.0 * 255.0 / mse);
        return new ImageComparison(psnr, (double) outliers / (w * h), diff);
    }
}

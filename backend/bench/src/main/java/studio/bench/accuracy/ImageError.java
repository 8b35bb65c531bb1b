package studio.bench.accuracy;

import studio.engine.render.Film;

/**
 * How far an image is from a reference, in linear light (the film's values, before sRGB encoding):
 * the root-mean-square error over every channel of every pixel, and the PSNR with a peak of 1.0
 * (white in linear light).
 */
public final class ImageError {

    private ImageError() {
    }

    /** RMSE over all channels of two films of the same size. */
    public static double rmse(Film image, Film reference) {
        if (image.width() != reference.width() || image.height() != reference.height()) {
            throw new IllegalArgumentException("the images differ in size: " + image.width() + "x" + image.height()
                    + " and " + reference.width() + "x" + reference.height());
        }
        double sum = 0;
        for (int y = 0; y < image.height(); y++) {
            for (int x = 0; x < image.width(); x++) {
                for (int c = 0; c < 3; c++) {
                    double d = image.get(x, y, c) - reference.get(x, y, c);
                    sum += d * d;
                }
            }
        }
        return Math.sqrt(sum / (3.0 * image.width() * image.height()));
    }

    /** RMSE of two arrays of channel values of the same length. */
    public static double rmse(double[] values, double[] reference) {
        if (values.length != reference.length || values.length == 0) {
            throw new IllegalArgumentException("need two non-empty arrays of the same length, not "
                    + values.length + " and " + reference.length);
        }
        double sum = 0;
        for (int i = 0; i < values.length; i++) {
            double d = values[i] - reference[i];
            sum += d * d;
        }
        return Math.sqrt(sum / values.length);
    }

    /** Peak signal-to-noise ratio in dB for a peak of 1.0 in linear light; infinite for a perfect match. */
    public static double psnr(double rmse) {
        if (!(rmse >= 0)) {
            throw new IllegalArgumentException("an RMSE is a non-negative number: " + rmse);
        }
        return rmse == 0 ? Double.POSITIVE_INFINITY : -20 * Math.log10(rmse);
    }
}

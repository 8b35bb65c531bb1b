package studio.engine.sampler;

/**
 * Stratified sampling: the pixel is cut into columns x rows = N cells (as square as N allows) and
 * each cell gets one uniformly random sample.
 */
public record JitteredSampler(int samplesPerPixel) implements Sampler {

    public JitteredSampler {
        if (samplesPerPixel < 1) {
            throw new IllegalArgumentException("samples per pixel must be at least 1: " + samplesPerPixel);
        }
    }

    /** The largest divisor of N not above its square root: the number of rows. */
    static int rows(int n) {
        int r = (int) Math.sqrt(n);
        while (n % r != 0) {
            r--;
        }
        return r;
    }

    @Override
    public void generate(PixelRandom random, double[] xs, double[] ys) {
        int rows = rows(samplesPerPixel), columns = samplesPerPixel / rows;
        for (int j = 0, i = 0; j < rows; j++) {
            for (int c = 0; c < columns; c++, i++) {
                xs[i] = (c + random.nextDouble()) / columns;
                ys[i] = (j + random.nextDouble()) / rows;
            }
        }
    }
}

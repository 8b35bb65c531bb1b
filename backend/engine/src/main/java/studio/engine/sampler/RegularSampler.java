package studio.engine.sampler;

/**
 * The original product's sampler: N = k*k samples at the centres of a k x k grid in each pixel.
 * Deterministic and cheap, but it aliases on patterns finer than the grid.
 */
public record RegularSampler(int samplesPerPixel) implements Sampler {

    public RegularSampler {
        int k = (int) Math.round(Math.sqrt(samplesPerPixel));
        if (samplesPerPixel < 1 || k * k != samplesPerPixel) {
            throw new IllegalArgumentException("the regular sampler needs a square number of samples "
                    + "(1, 4, 9, 16, ...), not " + samplesPerPixel);
        }
    }

    @Override
    public void generate(PixelRandom random, double[] xs, double[] ys) {
        int k = (int) Math.round(Math.sqrt(samplesPerPixel));
        for (int j = 0, i = 0; j < k; j++) {
            for (int c = 0; c < k; c++, i++) {
                xs[i] = (c + 0.5) / k;
                ys[i] = (j + 0.5) / k;
            }
        }
    }

    @Override
    public Sampler withSamplesPerPixel(int n) {
        return new RegularSampler(n);
    }
}

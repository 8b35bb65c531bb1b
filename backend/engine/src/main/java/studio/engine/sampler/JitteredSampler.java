package studio.engine.sampler;

/**
 * Stratified sampling: the pixel is cut into columns x rows = N cells (as square as N allows) and
 * each cell gets one uniformly random sample.
 */
public record JitteredSampler(int samplesPerPixel) implements Sampler {

    public JitteredSampler {
        Strata.requirePositive(samplesPerPixel);
    }

    @Override
    public void generate(PixelRandom random, double[] xs, double[] ys) {
        int rows = Strata.rows(samplesPerPixel), columns = samplesPerPixel / rows;
        for (int j = 0, i = 0; j < rows; j++) {
            for (int c = 0; c < columns; c++, i++) {
                xs[i] = Strata.offset(c, random.nextDouble(), columns);
                ys[i] = Strata.offset(j, random.nextDouble(), rows);
            }
        }
    }

    @Override
    public Sampler withSamplesPerPixel(int n) {
        return new JitteredSampler(n);
    }
}

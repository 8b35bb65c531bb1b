package studio.engine.sampler;

/**
 * Independent uniform samples over the pixel: unbiased and alias-free, but with no stratification
 * its error on edges falls only like N^-1/2 (robustness case SAM-02).
 */
public record RandomSampler(int samplesPerPixel) implements Sampler {

    public RandomSampler {
        Strata.requirePositive(samplesPerPixel);
    }

    @Override
    public void generate(PixelRandom random, double[] xs, double[] ys) {
        for (int i = 0; i < samplesPerPixel; i++) {
            xs[i] = random.nextDouble();
            ys[i] = random.nextDouble();
        }
    }

    @Override
    public Sampler withSamplesPerPixel(int n) {
        return new RandomSampler(n);
    }
}

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
    public String name() {
        return "random";
    }

    /** Two values (x, y) per sample. */
    @Override
    public int draws(int size) {
        return 2 * size;
    }

    @Override
    public void fill(PixelRandom random, int size, int first, int count, double[] xs, double[] ys) {
        random.skip(2L * first);
        for (int i = first; i < first + count; i++) {
            xs[i] = random.nextDouble();
            ys[i] = random.nextDouble();
        }
    }
}

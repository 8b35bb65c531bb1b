package studio.engine.sampler;

/**
 * The original product's sampler: N = k*k samples at the centres of a k x k grid in each pixel.
 * Deterministic and cheap, but it aliases on patterns finer than the grid.
 */
public record RegularSampler(int samplesPerPixel) implements Sampler {

    public RegularSampler {
        side(samplesPerPixel);
    }

    @Override
    public String name() {
        return "regular";
    }

    /** Nothing random. */
    @Override
    public int draws(int size) {
        return 0;
    }

    /** Sample i is at the centre of column i mod k and row i / k. */
    @Override
    public void fill(PixelRandom random, int size, int first, int count, double[] xs, double[] ys) {
        int k = side(size);
        for (int i = first; i < first + count; i++) {
            xs[i] = (i % k + 0.5) / k;
            ys[i] = (i / k + 0.5) / k;
        }
    }

    /** k for a pattern of k*k samples. */
    private static int side(int size) {
        int k = (int) Math.round(Math.sqrt(size));
        if (size < 1 || k * k != size) {
            throw new IllegalArgumentException("the regular sampler needs a square number of samples "
                    + "(1, 4, 9, 16, ...), not " + size);
        }
        return k;
    }
}

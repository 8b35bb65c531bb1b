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
    public String name() {
        return "jittered";
    }

    /** Two values (x, y) per sample. */
    @Override
    public int draws(int size) {
        return 2 * size;
    }

    /** Sample i sits in column i mod columns and row i / columns of the pattern's grid. */
    @Override
    public void fill(PixelRandom random, int size, int first, int count, double[] xs, double[] ys) {
        int rows = Strata.rows(size), columns = size / rows;
        random.skip(2L * first);
        int column = first % columns, row = first / columns;
        for (int i = first; i < first + count; i++) {
            xs[i] = Strata.offset(column, random.nextDouble(), columns);
            ys[i] = Strata.offset(row, random.nextDouble(), rows);
            if (++column == columns) {
                column = 0;
                row++;
            }
        }
    }
}

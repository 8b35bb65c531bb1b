package studio.engine.sampler;

/**
 * Multi-jittered sampling (Chiu, Shirley and Wang, "Multi-Jittered Sampling", Graphics Gems IV,
 * 1994): N = m x n samples, n rows by m columns as square as N allows (as {@link JitteredSampler}).
 * Each sample is jittered inside one cell of the m x n grid <em>and</em> inside one of N narrow
 * columns (width 1/N) and one of N narrow rows (height 1/N), so the pattern is stratified in 2D and
 * in each 1D projection at once.
 *
 * <p>The canonical arrangement puts the sample of cell (column i, row j) in narrow column i*n + j
 * and narrow row j*m + i; then the x offsets are shuffled among the cells of each column and the y
 * offsets among the cells of each row (independent Fisher-Yates shuffles), which keeps every
 * property while removing the canonical pattern's diagonal correlation.
 */
public record MultiJitteredSampler(int samplesPerPixel) implements Sampler {

    public MultiJitteredSampler {
        Strata.requirePositive(samplesPerPixel);
    }

    @Override
    public String name() {
        return "multijittered";
    }

    /** Two values per sample, and one per swap of the shuffles: n - 1 in each of m columns, m - 1 in each of n rows. */
    @Override
    public int draws(int size) {
        int n = Strata.rows(size), m = size / n;
        return 2 * size + m * (n - 1) + n * (m - 1);
    }

    /** The whole pattern, whichever samples are asked for: the shuffles leave no sample on its own. */
    @Override
    public void fill(PixelRandom random, int size, int first, int count, double[] xs, double[] ys) {
        int n = Strata.rows(size), m = size / n; // n rows, m columns
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < m; i++) {
                int s = j * m + i;
                xs[s] = Strata.offset(i * n + j, random.nextDouble(), size);
                ys[s] = Strata.offset(j * m + i, random.nextDouble(), size);
            }
        }
        // x within each column i: permute over the rows j
        for (int i = 0; i < m; i++) {
            for (int j = n - 1; j > 0; j--) {
                int k = random.nextInt(j + 1);
                double t = xs[j * m + i];
                xs[j * m + i] = xs[k * m + i];
                xs[k * m + i] = t;
            }
        }
        // y within each row j: permute over the columns i
        for (int j = 0; j < n; j++) {
            int row = j * m;
            for (int i = m - 1; i > 0; i--) {
                int k = random.nextInt(i + 1);
                double t = ys[row + i];
                ys[row + i] = ys[row + k];
                ys[row + k] = t;
            }
        }
    }
}

package studio.engine.geometry;

/**
 * A setup loop over n items as calls of {@value #LENGTH} items each. A render process runs without
 * on-stack replacement ({@code bin/studio}), so a loop inside one call stays interpreted to its end;
 * a body called run by run is compiled after its first hundred runs (docs/speed.md, "Where a cold
 * process's time goes").
 */
public final class Runs {

    /** Items a call. */
    public static final int LENGTH = 64;

    /** The body of a loop over items [from, to). */
    @FunctionalInterface
    public interface Body {
        void run(int from, int to);
    }

    private Runs() {
    }

    /** Runs {@code body} over [0, n) in order, {@value #LENGTH} items a call. */
    public static void over(int n, Body body) {
        for (int from = 0; from < n; from += LENGTH) {
            body.run(from, Math.min(n, from + LENGTH));
        }
    }
}

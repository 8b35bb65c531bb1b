package studio.engine.render;

/**
 * A finished render.
 *
 * @param raysTraced        primary, secondary and shadow rays
 * @param nonFiniteSamples  samples that came out NaN or infinite and were dropped (should be 0)
 */
public record RenderResult(Film film, long raysTraced, long nonFiniteSamples, long elapsedNanos) {

    public double raysPerSecond() {
        return elapsedNanos > 0 ? raysTraced * 1e9 / elapsedNanos : 0;
    }

    public long elapsedMillis() {
        return elapsedNanos / 1_000_000;
    }
}

package studio.engine.render;

/**
 * A finished render.
 *
 * @param raysTraced        primary, secondary and shadow rays
 * @param nonFiniteSamples  samples that came out NaN or infinite and were dropped (should be 0)
 * @param samplesTaken      camera samples over all pixels (width x height x samples per pixel, or
 *                          fewer with adaptive sampling)
 * @param cpuNanos          CPU time the render's threads spent rendering its tiles (each tile timed by
 *                          its thread's own clock, in nanoseconds: what the render cost whatever else the
 *                          machine did meanwhile); 0 where not measured (tiles rendered by other machines)
 */
public record RenderResult(Film film, long raysTraced, long nonFiniteSamples, long elapsedNanos,
                           long samplesTaken, long cpuNanos) {

    /** A render whose CPU time was not measured. */
    public RenderResult(Film film, long raysTraced, long nonFiniteSamples, long elapsedNanos, long samplesTaken) {
        this(film, raysTraced, nonFiniteSamples, elapsedNanos, samplesTaken, 0);
    }

    /** The mean number of samples a pixel took. */
    public double meanSamplesPerPixel() {
        return (double) samplesTaken / ((long) film.width() * film.height());
    }

    public double raysPerSecond() {
        return elapsedNanos > 0 ? raysTraced * 1e9 / elapsedNanos : 0;
    }

    public long elapsedMillis() {
        return elapsedNanos / 1_000_000;
    }
}

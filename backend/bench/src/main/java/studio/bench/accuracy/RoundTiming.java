package studio.bench.accuracy;

import java.util.Arrays;
import java.util.function.LongSupplier;
import java.util.function.Supplier;

import studio.engine.render.RenderResult;

/**
 * One setting's time in one round: a render shorter than {@link #FILL_MILLIS} is repeated until
 * the round's renders of it fill that long (at most {@link #MAX_RENDERS}), and the median of them
 * counts, wall and CPU time apart. One render of 15-60 ms measured the machine's moment as much
 * as the render (on the chart's stripes, one JVM timed threshold 0.5 slower than 0.2, which does
 * more work); the 256-sample renders, which take most of a round, still render once.
 *
 * @param millis    median wall time of the renders, in ms
 * @param cpuMillis median CPU time of the renders' threads, in ms
 * @param first     the first render's result (its image gives the setting's error)
 */
record RoundTiming(double millis, double cpuMillis, RenderResult first) {

    /** Renders shorter than this are repeated within a round until they fill it. */
    static final double FILL_MILLIS = 250;
    /** The most renders of one setting in one round. */
    static final int MAX_RENDERS = 25;

    static RoundTiming of(Supplier<RenderResult> render) {
        return of(render, System::nanoTime);
    }

    /** {@link #of(Supplier)} on the given clock (nanoseconds). */
    static RoundTiming of(Supplier<RenderResult> render, LongSupplier nanoClock) {
        double[] wall = new double[MAX_RENDERS], cpu = new double[MAX_RENDERS];
        double total = 0;
        int n = 0;
        RenderResult first = null;
        do {
            long start = nanoClock.getAsLong();
            RenderResult result = render.get();
            wall[n] = (nanoClock.getAsLong() - start) / 1e6;
            cpu[n] = result.cpuNanos() / 1e6;
            total += wall[n];
            if (first == null) {
                first = result;
            }
            n++;
        } while (total < FILL_MILLIS && n < MAX_RENDERS);
        return new RoundTiming(SpeedAccuracyBench.median(Arrays.copyOf(wall, n)),
                SpeedAccuracyBench.median(Arrays.copyOf(cpu, n)), first);
    }
}

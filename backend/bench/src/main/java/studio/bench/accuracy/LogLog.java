package studio.bench.accuracy;

import java.util.OptionalDouble;

/** Straight lines through log-log data: convergence slopes and the cost of reaching an error. */
public final class LogLog {

    private LogLog() {
    }

    /**
     * The least-squares slope of log(y) against log(x): -0.5 for plain Monte Carlo noise, steeper
     * for stratified sampling of smooth pixels.
     *
     * @return NaN with fewer than two points, or if any value is not positive, or if all x are equal
     */
    public static double slope(double[] xs, double[] ys) {
        if (xs.length != ys.length) {
            throw new IllegalArgumentException("x and y differ in length: " + xs.length + " and " + ys.length);
        }
        int n = xs.length;
        if (n < 2) {
            return Double.NaN;
        }
        double sx = 0, sy = 0;
        for (int i = 0; i < n; i++) {
            if (!(xs[i] > 0) || !(ys[i] > 0)) {
                return Double.NaN;
            }
            sx += Math.log(xs[i]);
            sy += Math.log(ys[i]);
        }
        double mx = sx / n, my = sy / n, sxx = 0, sxy = 0;
        for (int i = 0; i < n; i++) {
            double dx = Math.log(xs[i]) - mx;
            sxx += dx * dx;
            sxy += dx * (Math.log(ys[i]) - my);
        }
        return sxx > 0 ? sxy / sxx : Double.NaN;
    }

    /**
     * The time at which a method's error first falls to {@code target}, interpolating linearly in
     * log(time), log(error) between consecutive measurements (in the order given: increasing samples).
     *
     * @return the time; empty if no measurement reaches the target. If the first measurement is
     *         already at or below it, that measurement's time (an upper bound: see {@link #reachedAtFirst}).
     */
    public static OptionalDouble timeToReach(double[] times, double[] errors, double target) {
        if (times.length != errors.length) {
            throw new IllegalArgumentException("times and errors differ in length: " + times.length + " and " + errors.length);
        }
        if (times.length == 0 || !(target > 0)) {
            return OptionalDouble.empty();
        }
        if (errors[0] <= target) {
            return OptionalDouble.of(times[0]);
        }
        for (int i = 1; i < times.length; i++) {
            if (errors[i] <= target) {
                double e0 = Math.log(errors[i - 1]), e1 = Math.log(errors[i]);
                double t0 = Math.log(times[i - 1]), t1 = Math.log(times[i]);
                if (!(errors[i] > 0) || e0 == e1) {
                    return OptionalDouble.of(times[i]);
                }
                double f = (e0 - Math.log(target)) / (e0 - e1);
                return OptionalDouble.of(Math.exp(t0 + f * (t1 - t0)));
            }
        }
        return OptionalDouble.empty();
    }

    /** True if the first measurement already reaches the target, so its time is only an upper bound. */
    public static boolean reachedAtFirst(double[] errors, double target) {
        return errors.length > 0 && errors[0] <= target;
    }
}

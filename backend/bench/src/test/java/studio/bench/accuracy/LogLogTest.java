package studio.bench.accuracy;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.Random;

import org.junit.jupiter.api.Test;

class LogLogTest {

    @Test
    void slopeOfAPowerLawIsItsExponent() {
        double[] samples = {4, 16, 64, 256};
        double[] half = new double[4], one = new double[4];
        for (int i = 0; i < 4; i++) {
            half[i] = 0.3 * Math.pow(samples[i], -0.5);
            one[i] = 2.0 / samples[i];
        }
        assertThat(LogLog.slope(samples, half)).isCloseTo(-0.5, within(1e-12));
        assertThat(LogLog.slope(samples, one)).isCloseTo(-1.0, within(1e-12));
    }

    @Test
    void slopeIsTheLeastSquaresFit() {
        // logs (0,0), (L,0), (2L,2L): mean (L, 2L/3); sxy = 2L^2, sxx = 2L^2
        assertThat(LogLog.slope(new double[] {1, 2, 4}, new double[] {1, 1, 4})).isCloseTo(1.0, within(1e-12));
    }

    @Test
    void slopeRecoversTheExponentThroughNoise() {
        Random random = new Random(1);
        double[] xs = new double[200], ys = new double[200];
        for (int i = 0; i < xs.length; i++) {
            xs[i] = Math.pow(2, 2 + 6 * random.nextDouble());
            ys[i] = 0.1 * Math.pow(xs[i], -0.75) * Math.exp(0.05 * random.nextGaussian());
        }
        assertThat(LogLog.slope(xs, ys)).isCloseTo(-0.75, within(0.02));
    }

    @Test
    void slopeIsUndefinedWithoutTwoDistinctPositivePoints() {
        assertThat(LogLog.slope(new double[] {4}, new double[] {0.1})).isNaN();
        assertThat(LogLog.slope(new double[] {4, 4}, new double[] {0.1, 0.2})).isNaN();
        assertThat(LogLog.slope(new double[] {4, 16}, new double[] {0.1, 0})).isNaN();
    }

    @Test
    void timeToReachInterpolatesInLogLog() {
        double[] times = {10, 40, 160}, errors = {0.1, 0.05, 0.025};
        // half-way in log error between 0.1 and 0.05 is half-way in log time: sqrt(10 * 40)
        assertThat(LogLog.timeToReach(times, errors, Math.sqrt(0.1 * 0.05)).getAsDouble()).isCloseTo(20, within(1e-9));
        assertThat(LogLog.timeToReach(times, errors, 0.05).getAsDouble()).isCloseTo(40, within(1e-9));
        // a quarter of the way in log error between 0.05 and 0.025
        assertThat(LogLog.timeToReach(times, errors, 0.05 * Math.pow(0.5, 0.25)).getAsDouble())
                .isCloseTo(40 * Math.pow(4, 0.25), within(1e-9));
    }

    @Test
    void timeToReachTakesTheFirstCrossing() {
        // not monotone (an aliasing sampler can do this): the error is reached between the first two points
        double[] times = {10, 20, 40}, errors = {0.1, 0.02, 0.05};
        double t = LogLog.timeToReach(times, errors, 0.03).getAsDouble();
        assertThat(t).isBetween(10.0, 20.0);
        double f = Math.log(0.1 / 0.03) / Math.log(0.1 / 0.02);
        assertThat(t).isCloseTo(Math.exp(Math.log(10) + f * Math.log(2)), within(1e-9));
    }

    @Test
    void timeToReachIsEmptyWhenNeverReachedAndTheFirstTimeWhenAlreadyThere() {
        double[] times = {10, 40}, errors = {0.1, 0.05};
        assertThat(LogLog.timeToReach(times, errors, 0.01)).isEmpty();
        assertThat(LogLog.timeToReach(times, errors, 0.2).getAsDouble()).isEqualTo(10);
        assertThat(LogLog.reachedAtFirst(errors, 0.2)).isTrue();
        assertThat(LogLog.reachedAtFirst(errors, 0.07)).isFalse();
    }
}

package studio.bench.accuracy;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;

import org.junit.jupiter.api.Test;

import studio.engine.render.Film;
import studio.engine.render.RenderResult;

class RoundTimingTest {

    /** Renders that advance a fake clock by the given milliseconds in turn (the last repeats), CPU twice the wall. */
    private static final class FakeRenders implements Supplier<RenderResult> {
        final List<RenderResult> made = new ArrayList<>();
        private final double[] millis;
        private long now;

        FakeRenders(double... millis) {
            this.millis = millis;
        }

        @Override
        public RenderResult get() {
            double ms = millis[Math.min(made.size(), millis.length - 1)];
            now += (long) (ms * 1e6);
            RenderResult result = new RenderResult(new Film(1, 1), 0, 0, 0, 1, (long) (2 * ms * 1e6));
            made.add(result);
            return result;
        }

        /** One round's timing of these renders, on their own clock. */
        RoundTiming timed() {
            return RoundTiming.of(this, () -> now);
        }
    }

    @Test
    void aLongRenderIsTimedOnce() {
        FakeRenders renders = new FakeRenders(300);
        RoundTiming timing = renders.timed();
        assertThat(renders.made).hasSize(1);
        assertThat(timing.millis()).isEqualTo(300);
        assertThat(timing.cpuMillis()).isEqualTo(600);
        assertThat(timing.first()).isSameAs(renders.made.get(0));
    }

    @Test
    void aShortRenderRepeatsUntilTheRoundIsFilledAndItsMedianCounts() {
        // 40 ms, then a 100 ms outlier, then 50 ms each: 40 + 100 + 50 + 50 + 50 = 290 >= 250 after five
        FakeRenders renders = new FakeRenders(40, 100, 50);
        RoundTiming timing = renders.timed();
        assertThat(renders.made).hasSize(5);
        assertThat(timing.millis()).isEqualTo(50);
        assertThat(timing.cpuMillis()).isEqualTo(100);
        assertThat(timing.first()).isSameAs(renders.made.get(0));
    }

    @Test
    void aVeryShortRenderStopsAtTheMostRenders() {
        FakeRenders renders = new FakeRenders(1);
        RoundTiming timing = renders.timed();
        assertThat(renders.made).hasSize(RoundTiming.MAX_RENDERS);
        assertThat(timing.millis()).isEqualTo(1);
    }
}

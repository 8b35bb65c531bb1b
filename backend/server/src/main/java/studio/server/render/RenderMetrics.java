package studio.server.render;

import java.util.EnumMap;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import io.micrometer.core.instrument.Counter;
import io.micrometer.core.instrument.DistributionSummary;
import io.micrometer.core.instrument.MeterRegistry;
import io.micrometer.core.instrument.Timer;
import io.micrometer.core.instrument.simple.SimpleMeterRegistry;

import studio.engine.render.RenderResult;

/**
 * The renders' figures in the service's metrics (Prometheus names at {@code /actuator/prometheus}),
 * by kind of render ({@code kind="sync"}, {@code "job"} or {@code "live_view"}, one pass of a live
 * view being one render):
 * <ul>
 *   <li>{@code studio_render_seconds}: a timer of the renders that finished (count, sum, max);</li>
 *   <li>{@code studio_rays_total}: the rays they traced, whose rate is the service's rays per second;</li>
 *   <li>{@code studio_render_rays_per_second}: each render's own speed (count, sum, max).</li>
 * </ul>
 * A render that was cancelled or ran out of time is not counted. Recording costs a few
 * nanoseconds, once per render, never per tile or ray.
 */
public final class RenderMetrics {

    /** What asked for a render. */
    public enum Kind {
        /** {@code POST /api/render}. */
        SYNC,
        /** A render job ({@code POST /api/jobs}), on this member or the cluster. */
        JOB,
        /** One pass of a live view ({@code /api/preview}). */
        LIVE_VIEW;

        String tag() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    private record Meters(Timer time, Counter rays, DistributionSummary speed) {
    }

    private final Map<Kind, Meters> meters = new EnumMap<>(Kind.class);

    public RenderMetrics(MeterRegistry registry) {
        for (Kind kind : Kind.values()) {
            meters.put(kind, new Meters(
                    Timer.builder("studio.render").description("Renders that finished, by kind")
                            .tag("kind", kind.tag()).register(registry),
                    Counter.builder("studio.rays").description("Rays traced by the renders that finished, by kind")
                            .tag("kind", kind.tag()).register(registry),
                    DistributionSummary.builder("studio.render.rays.per.second")
                            .description("Each finished render's rays per second, by kind")
                            .tag("kind", kind.tag()).register(registry)));
        }
    }

    /** Figures kept in memory only (the command line, tests that build services by hand). */
    public static RenderMetrics unpublished() {
        return new RenderMetrics(new SimpleMeterRegistry());
    }

    /** Counts a render that finished. */
    public void rendered(Kind kind, RenderResult result) {
        Meters m = meters.get(kind);
        m.time().record(result.elapsedNanos(), TimeUnit.NANOSECONDS);
        m.rays().increment(result.raysTraced());
        if (result.elapsedNanos() > 0) {
            m.speed().record(result.raysPerSecond());
        }
    }
}

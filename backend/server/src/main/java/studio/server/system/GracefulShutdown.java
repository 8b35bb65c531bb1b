package studio.server.system;

import java.time.Duration;
import java.util.List;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.springframework.context.SmartLifecycle;

/**
 * Lets the renders in hand finish when the service is told to stop (SIGTERM), while the web server
 * still serves: new work is refused at once (503 or 429 with Retry-After) and work that has not
 * started ends cancelled; running renders may finish within the grace period, after which they are
 * cancelled (they stop within a tile); event streams hear their job's end; a synchronous render gets
 * its image or a 503 problem. Only then does the web server's own graceful shutdown begin (it runs
 * in a later phase), so that clients can still fetch a finished job's image during the grace period.
 *
 * <p>The drain runs in {@link #stop()}, synchronously: Spring's per-phase shutdown timeout
 * (spring.lifecycle.timeout-per-shutdown-phase) bounds only the web server's wait for the
 * connections that are still open afterwards.
 */
public final class GracefulShutdown implements SmartLifecycle {

    private static final Logger log = LoggerFactory.getLogger(GracefulShutdown.class);

    private final List<Drainable> work;
    private final Duration grace;
    private volatile boolean running;

    public GracefulShutdown(List<Drainable> work, Duration grace) {
        this.work = List.copyOf(work);
        this.grace = grace;
    }

    @Override
    public void start() {
        running = true;
    }

    @Override
    public void stop() {
        if (!running) {
            return;
        }
        running = false;
        long start = System.nanoTime();
        if (!Drainable.drain(work, grace.toMillis())) {
            log.info("shutting down: the renders still running after the grace period of {} were cancelled", grace);
        }
        log.info("shutting down: renders drained in {} ms", (System.nanoTime() - start) / 1_000_000);
    }

    /**
     * Not stopped when the context is only paused (Spring's test framework pauses a cached context
     * it is not using, and restarts it later): the drain refuses new work for good, as a service
     * being shut down must.
     */
    @Override
    public boolean isPauseable() {
        return false;
    }

    @Override
    public boolean isRunning() {
        return running;
    }
}

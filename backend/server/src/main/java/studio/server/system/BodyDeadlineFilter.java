package studio.server.system;

import java.io.IOException;
import java.time.Duration;

import org.springframework.util.unit.DataSize;
import org.springframework.web.filter.OncePerRequestFilter;

import jakarta.servlet.FilterChain;
import jakarta.servlet.ServletException;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * Answers 408 when a request body arrives too slowly: it may take {@code grace}, and then as long
 * again as its bytes need at {@code minRate} a second (the defaults: 10 s and 256 KiB/s, so a
 * 32 MiB body may take 2 min 18 s). It is checked each time a read returns, so a client trickling
 * one byte every few seconds is cut off soon after the grace, with a problem; one that sends
 * nothing at all is cut off by the container's read timeout (server.tomcat.connection-timeout,
 * 60 s by default, also a 408), holding meanwhile only the memory of what it sent ({@link IntakeMemory}).
 */
final class BodyDeadlineFilter extends OncePerRequestFilter {

    private final long graceNanos;
    private final long minBytesPerSecond;

    BodyDeadlineFilter(Duration grace, DataSize minRate) {
        if (grace.isNegative() || minRate.toBytes() <= 0) {
            throw new IllegalArgumentException("a body's grace must not be negative and its minimum rate must be "
                    + "positive: " + grace + ", " + minRate);
        }
        this.graceNanos = grace.toNanos();
        this.minBytesPerSecond = minRate.toBytes();
    }

    @Override
    protected void doFilterInternal(HttpServletRequest request, HttpServletResponse response, FilterChain chain)
            throws ServletException, IOException {
        long start = System.nanoTime();
        long[] received = new long[1];
        chain.doFilter(new WatchedBody(request, (buffer, offset, length) -> {
            received[0] += length;
            long elapsed = System.nanoTime() - start;
            if (elapsed > graceNanos && (double) (elapsed - graceNanos) / 1e9 * minBytesPerSecond > received[0]) {
                throw new BodyTimeoutException(String.format(java.util.Locale.ROOT, "the request body came too "
                        + "slowly: %d bytes in %.1f s; after %d s a body must keep coming at %d KiB/s on average "
                        + "(studio.limits.body-grace, studio.limits.min-body-rate)", received[0], elapsed / 1e9,
                        Duration.ofNanos(graceNanos).toSeconds(), minBytesPerSecond >> 10));
            }
        }), response);
    }
}

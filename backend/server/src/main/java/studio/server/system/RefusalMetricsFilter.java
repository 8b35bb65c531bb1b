package studio.server.system;

import java.io.IOException;

import org.springframework.web.filter.OncePerRequestFilter;

import io.micrometer.core.instrument.MeterRegistry;
import jakarta.servlet.FilterChain;
import jakarta.servlet.ServletException;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * Counts the API's refusals by status in the metrics, {@code studio_refusals_total{status="429"}}
 * and so on: every answer of 400 or more, whichever part gave it (a filter's 413 or 408, the
 * advice's 400, a full queue's 429, a busy server's 503, a live view's refused upgrade). The first
 * filter of the chain, so that it sees the others' answers; an asynchronous answer is counted when
 * it is complete.
 */
final class RefusalMetricsFilter extends OncePerRequestFilter {

    private final MeterRegistry registry;

    RefusalMetricsFilter(MeterRegistry registry) {
        this.registry = registry;
    }

    @Override
    protected boolean shouldNotFilterAsyncDispatch() {
        return false;
    }

    @Override
    protected void doFilterInternal(HttpServletRequest request, HttpServletResponse response, FilterChain chain)
            throws ServletException, IOException {
        boolean failed = true;
        try {
            chain.doFilter(request, response);
            failed = false;
        } finally {
            if (!request.isAsyncStarted()) {
                // an exception that escaped the chain becomes a 500 beyond this filter
                count(failed && response.getStatus() < 400 ? 500 : response.getStatus());
            }
        }
    }

    private void count(int status) {
        if (status >= 400) {
            registry.counter("studio.refusals", "status", Integer.toString(status)).increment();
        }
    }
}

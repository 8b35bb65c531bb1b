package studio.server.system;

import java.io.IOException;

import org.springframework.http.HttpHeaders;
import org.springframework.http.MediaType;
import org.springframework.web.filter.OncePerRequestFilter;

import jakarta.servlet.FilterChain;
import jakarta.servlet.ServletException;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * Reserves the memory a request body takes while it is read and turned into a scene (the bytes,
 * the JSON tree, the records and the engine's objects: {@value #INTAKE_FACTOR} times the body) from
 * the {@link MemoryBudget} before reading it, and gives it back when the request has been handled
 * (an asynchronous render keeps its own reservation). When the budget cannot cover it, the
 * request gets 503 with Retry-After and the body is never read: many large bodies at once cannot
 * exhaust the heap. A body without a declared length counts at the body limit.
 */
final class IntakeMemoryFilter extends OncePerRequestFilter {

    static final int INTAKE_FACTOR = 8;
    static final int RETRY_AFTER_SECONDS = 2;

    private final MemoryBudget budget;
    private final long maxBodyBytes;

    IntakeMemoryFilter(MemoryBudget budget, long maxBodyBytes) {
        this.budget = budget;
        this.maxBodyBytes = maxBodyBytes;
    }

    @Override
    protected boolean shouldNotFilter(HttpServletRequest request) {
        return !"POST".equals(request.getMethod()) && !"PUT".equals(request.getMethod());
    }

    @Override
    protected void doFilterInternal(HttpServletRequest request, HttpServletResponse response, FilterChain chain)
            throws ServletException, IOException {
        long declared = request.getContentLengthLong();
        long body = declared >= 0 ? Math.min(declared, maxBodyBytes) : maxBodyBytes;
        MemoryBudget.Reservation reservation = budget.tryReserve(body * INTAKE_FACTOR);
        if (reservation == null) {
            response.setStatus(503);
            response.setHeader(HttpHeaders.RETRY_AFTER, Integer.toString(RETRY_AFTER_SECONDS));
            response.setContentType(MediaType.APPLICATION_PROBLEM_JSON_VALUE);
            response.getWriter().write("{\"type\":\"about:blank\",\"title\":\"Service Unavailable\",\"status\":503,"
                    + "\"detail\":\"the server is reading or rendering as much as its memory allows; try again in "
                    + RETRY_AFTER_SECONDS + " s\"}");
            return;
        }
        try (reservation) {
            chain.doFilter(request, response);
        }
    }
}

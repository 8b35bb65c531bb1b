package studio.server.system;

import java.io.IOException;
import java.util.Locale;

import org.springframework.web.filter.OncePerRequestFilter;

import jakarta.servlet.AsyncEvent;
import jakarta.servlet.AsyncListener;
import jakarta.servlet.FilterChain;
import jakarta.servlet.ServletException;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * Gives every request with a body its {@link IntakeMemory}: the body reserves what it will take as
 * it arrives, the scene compiler what the engine asks for, and what is left is given back when the
 * request has been handled (a render or a job takes its share over before). Nothing is reserved
 * for a declared Content-Length before the bytes come: a client that declares 32 MiB and sends one
 * byte holds what that byte will take (8 bytes, 168 for a <code>{</code>), so idle clients cannot
 * lock others out (61 that declared 32 MiB each held 12 KiB in all, where they had held the whole
 * budget). A body that is not JSON (an asset's bytes) is reckoned as raw bytes, not as a parse.
 */
final class IntakeMemoryFilter extends OncePerRequestFilter {

    private final MemoryBudget budget;

    IntakeMemoryFilter(MemoryBudget budget) {
        this.budget = budget;
    }

    @Override
    protected boolean shouldNotFilter(HttpServletRequest request) {
        return !"POST".equals(request.getMethod()) && !"PUT".equals(request.getMethod());
    }

    @Override
    protected void doFilterInternal(HttpServletRequest request, HttpServletResponse response, FilterChain chain)
            throws ServletException, IOException {
        IntakeMemory intake = IntakeMemory.of(budget);
        boolean arriving = false;
        try {
            intake.attachTo(request);
            String type = request.getContentType();
            boolean json = type == null || type.toLowerCase(Locale.ROOT).contains("json");
            chain.doFilter(new WatchedBody(request, json ? intake::bodyArrived : intake::rawBodyArrived), response);
            arriving = request.isAsyncStarted() && request.getAttribute(BodyArrivalFilter.ARRIVING) != null;
        } finally {
            if (arriving) {
                request.getAsyncContext().addListener(new CloseWhenHandled(intake));
            } else {
                intake.close();
            }
        }
    }

    /**
     * Closes a request's memory once the body that arrived in the background has been handled: when
     * the request completes, or when its controller starts work of its own (a render's answer, which
     * takes the memory over before).
     */
    private record CloseWhenHandled(IntakeMemory intake) implements AsyncListener {

        @Override
        public void onStartAsync(AsyncEvent event) {
            intake.close();
        }

        @Override
        public void onComplete(AsyncEvent event) {
            intake.close();
        }

        @Override
        public void onTimeout(AsyncEvent event) {
        }

        @Override
        public void onError(AsyncEvent event) {
        }
    }
}

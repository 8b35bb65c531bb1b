package studio.server.security;

import java.io.IOException;
import java.util.List;

import org.springframework.security.authentication.UsernamePasswordAuthenticationToken;
import org.springframework.security.core.context.SecurityContext;
import org.springframework.security.core.context.SecurityContextHolder;
import org.springframework.web.filter.OncePerRequestFilter;

import jakarta.servlet.FilterChain;
import jakarta.servlet.ServletException;
import jakarta.servlet.http.HttpServletRequest;
import jakarta.servlet.http.HttpServletResponse;

/**
 * Signs in the live view's upgrade ({@code /api/preview?ticket=}) as the principal its ticket was issued
 * to, using the ticket up; an unknown, used or expired ticket gets 401. Any other request passes as it came.
 */
final class TicketFilter extends OncePerRequestFilter {

    static final String PATH = "/api/preview";
    static final String PARAMETER = "ticket";

    private final PreviewTickets tickets;
    private final SecurityProblems problems;

    TicketFilter(PreviewTickets tickets, SecurityProblems problems) {
        this.tickets = tickets;
        this.problems = problems;
    }

    @Override
    protected boolean shouldNotFilter(HttpServletRequest request) {
        return !PATH.equals(request.getRequestURI()) || request.getParameter(PARAMETER) == null;
    }

    @Override
    protected void doFilterInternal(HttpServletRequest request, HttpServletResponse response, FilterChain chain)
            throws ServletException, IOException {
        String principal = tickets.consume(request.getParameter(PARAMETER));
        if (principal == null) {
            problems.commence(request, response, new SecurityProblems.BadTicketException());
            return;
        }
        SecurityContext context = SecurityContextHolder.createEmptyContext();
        context.setAuthentication(UsernamePasswordAuthenticationToken.authenticated(principal, null, List.of()));
        SecurityContextHolder.setContext(context);
        chain.doFilter(request, response);
    }
}

package studio.server.security;

import java.security.Principal;

import org.springframework.http.HttpHeaders;
import org.springframework.http.HttpStatus;
import org.springframework.http.ProblemDetail;
import org.springframework.web.ErrorResponseException;
import org.springframework.web.bind.annotation.GetMapping;
import org.springframework.web.bind.annotation.PostMapping;
import org.springframework.web.bind.annotation.RestController;

/** Who is signed in ({@code GET /api/me}), and tickets for the live view ({@code POST /api/preview/tickets}). */
@RestController
class SignInController {

    /** The caller: their principal ("" with sign-in off) and whether this server asks callers to sign in. */
    record Me(String principal, boolean signInRequired) {
    }

    /** A live view's ticket, to pass as {@code /api/preview?ticket=} within {@code expiresInSeconds}. */
    record Ticket(String ticket, long expiresInSeconds) {
    }

    private final SignIn signIn;
    private final PreviewTickets tickets;

    SignInController(SignIn signIn, PreviewTickets tickets) {
        this.signIn = signIn;
        this.tickets = tickets;
    }

    @GetMapping("/api/me")
    Me me(Principal principal) {
        return new Me(SignIn.principal(principal), signIn.required());
    }

    @PostMapping("/api/preview/tickets")
    Ticket ticket(Principal principal) {
        String ticket = tickets.issue(SignIn.principal(principal));
        long seconds = tickets.lifetime().toSeconds();
        if (ticket == null) {
            ErrorResponseException refused = new ErrorResponseException(HttpStatus.TOO_MANY_REQUESTS,
                    ProblemDetail.forStatusAndDetail(HttpStatus.TOO_MANY_REQUESTS, "too many unused live-view "
                            + "tickets (studio.security.max-tickets-per-principal); use one, or try again in "
                            + seconds + " s"), null);
            refused.getHeaders().set(HttpHeaders.RETRY_AFTER, Long.toString(seconds));
            throw refused;
        }
        return new Ticket(ticket, seconds);
    }
}

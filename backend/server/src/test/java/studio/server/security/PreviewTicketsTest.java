package studio.server.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.Base64;
import java.util.concurrent.atomic.AtomicLong;

import org.junit.jupiter.api.Test;

/** The live view's tickets without a server: single use, short life, a bounded store. */
class PreviewTicketsTest {

    private final AtomicLong now = new AtomicLong(1_000_000_000L);
    private final PreviewTickets tickets = new PreviewTickets(Duration.ofSeconds(30), 2, 3, now::get);

    @Test
    void ticketIsThirtyTwoRandomBytesInBase64Url() {
        String ticket = tickets.issue("alice");
        assertThat(Base64.getUrlDecoder().decode(ticket)).hasSize(32);
        assertThat(ticket).doesNotContain("=", "+", "/");
        assertThat(tickets.issue("alice")).isNotEqualTo(ticket);
    }

    @Test
    void ticketNamesItsPrincipalOnceThenNever() {
        String ticket = tickets.issue("alice");
        assertThat(tickets.consume(ticket)).isEqualTo("alice");
        assertThat(tickets.consume(ticket)).isNull();
    }

    @Test
    void ticketExpiresAfterItsLifetime() {
        String kept = tickets.issue("alice");
        String late = tickets.issue("bob");
        now.addAndGet(Duration.ofSeconds(30).toNanos());
        assertThat(tickets.consume(kept)).isEqualTo("alice");
        now.addAndGet(1);
        assertThat(tickets.consume(late)).isNull();
    }

    @Test
    void unknownTicketNamesNobody() {
        assertThat(tickets.consume("not-a-ticket")).isNull();
    }

    @Test
    void storeCapsUnusedTicketsPerPrincipalAndOverall() {
        assertThat(tickets.issue("alice")).isNotNull();
        String second = tickets.issue("alice");
        assertThat(second).isNotNull();
        assertThat(tickets.issue("alice")).as("a third unused ticket of alice's").isNull();
        assertThat(tickets.issue("bob")).isNotNull();
        assertThat(tickets.issue("carol")).as("a fourth unused ticket on the server").isNull();

        tickets.consume(second);
        assertThat(tickets.issue("alice")).as("after using one").isNotNull();
    }

    @Test
    void expiredTicketsMakeRoomAgain() {
        tickets.issue("alice");
        tickets.issue("alice");
        now.addAndGet(Duration.ofSeconds(31).toNanos());
        assertThat(tickets.issue("alice")).isNotNull();
    }
}

package studio.server.security;

import java.security.SecureRandom;
import java.time.Duration;
import java.util.Base64;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.LongSupplier;

/**
 * Short-lived, single-use tickets for the live view: a browser cannot set headers on a WebSocket, so it
 * asks for a ticket with its key ({@code POST /api/preview/tickets}) and passes it in the URL of the
 * upgrade ({@code /api/preview?ticket=}). A ticket is 32 random bytes (base64url), lives
 * {@code studio.security.ticket-lifetime}, and is consumed on its first use. The store is bounded, per
 * principal and overall, so that issuing tickets cannot fill the server's memory.
 */
final class PreviewTickets {

    private record Ticket(String principal, long expiresNanos) {
    }

    private static final SecureRandom RANDOM = new SecureRandom();

    private final Duration lifetime;
    private final int maxPerPrincipal;
    private final int max;
    private final LongSupplier nanos;
    /** Unused tickets, oldest first (each lives as long, so also soonest to expire first). */
    private final Map<String, Ticket> tickets = new LinkedHashMap<>();

    PreviewTickets(Duration lifetime, int maxPerPrincipal, int max, LongSupplier nanos) {
        this.lifetime = lifetime;
        this.maxPerPrincipal = maxPerPrincipal;
        this.max = max;
        this.nanos = nanos;
    }

    Duration lifetime() {
        return lifetime;
    }

    /**
     * A new ticket for {@code principal}, or null when they hold {@code maxPerPrincipal} unused ones or
     * the server holds {@code max}.
     */
    synchronized String issue(String principal) {
        long now = nanos.getAsLong();
        dropExpired(now);
        int theirs = 0;
        for (Ticket ticket : tickets.values()) {
            theirs += ticket.principal().equals(principal) ? 1 : 0;
        }
        if (theirs >= maxPerPrincipal || tickets.size() >= max) {
            return null;
        }
        byte[] bytes = new byte[32];
        RANDOM.nextBytes(bytes);
        String ticket = Base64.getUrlEncoder().withoutPadding().encodeToString(bytes);
        tickets.put(ticket, new Ticket(principal, now + lifetime.toNanos()));
        return ticket;
    }

    /** The principal a ticket was issued to, or null if it is unknown, used or expired; it is used up either way. */
    synchronized String consume(String ticket) {
        Ticket found = tickets.remove(ticket);
        if (found == null || nanos.getAsLong() - found.expiresNanos() > 0) {
            return null;
        }
        return found.principal();
    }

    private void dropExpired(long now) {
        for (Iterator<Ticket> it = tickets.values().iterator(); it.hasNext(); ) {
            if (now - it.next().expiresNanos() > 0) {
                it.remove();
            } else {
                break;
            }
        }
    }
}

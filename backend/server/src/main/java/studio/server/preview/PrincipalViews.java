package studio.server.preview;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

import org.springframework.web.socket.CloseStatus;
import org.springframework.web.socket.WebSocketHandler;
import org.springframework.web.socket.WebSocketSession;
import org.springframework.web.socket.handler.WebSocketHandlerDecorator;

/**
 * Live views open per principal, so that one principal cannot take every view the server serves: with
 * sign-in on, at most {@code studio.security.max-live-views-per-principal} each (one more gets 429); with
 * sign-in off, unlimited (only studio.preview.max-sessions counts). A place is taken at the handshake
 * ({@link SessionLimit}) and given back when the view closes, or when its handshake fails.
 */
final class PrincipalViews {

    /** The session attribute that names the principal whose place a view holds. */
    static final String PRINCIPAL = "studio.preview.principal";

    private final int maxPerPrincipal;
    private final Map<String, Integer> open = new ConcurrentHashMap<>();

    PrincipalViews(int maxPerPrincipal) {
        this.maxPerPrincipal = maxPerPrincipal;
    }

    int maxPerPrincipal() {
        return maxPerPrincipal;
    }

    /** Takes a place for the principal's new view; false when they have all theirs open. */
    boolean tryOpen(String principal) {
        if (maxPerPrincipal == Integer.MAX_VALUE) {
            return true;
        }
        boolean[] taken = {false};
        open.compute(principal, (name, count) -> {
            int now = count == null ? 0 : count;
            taken[0] = now < maxPerPrincipal;
            return taken[0] ? now + 1 : (count == null ? null : count);
        });
        return taken[0];
    }

    void release(String principal) {
        if (maxPerPrincipal != Integer.MAX_VALUE && principal != null) {
            open.computeIfPresent(principal, (name, count) -> count > 1 ? count - 1 : null);
        }
    }

    /** The handler, giving each closed view's place back to its principal. */
    WebSocketHandler releasingOnClose(WebSocketHandler handler) {
        return new WebSocketHandlerDecorator(handler) {
            @Override
            public void afterConnectionClosed(WebSocketSession session, CloseStatus status) throws Exception {
                try {
                    super.afterConnectionClosed(session, status);
                } finally {
                    release((String) session.getAttributes().remove(PRINCIPAL));
                }
            }
        };
    }
}

package studio.server.preview;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

import org.springframework.http.HttpHeaders;
import org.springframework.http.HttpMethod;
import org.springframework.http.HttpStatus;
import org.springframework.http.MediaType;
import org.springframework.http.server.ServerHttpRequest;
import org.springframework.http.server.ServerHttpResponse;
import org.springframework.http.server.ServletServerHttpResponse;
import org.springframework.web.socket.WebSocketHandler;
import org.springframework.web.socket.server.HandshakeInterceptor;
import org.springframework.web.util.WebUtils;

import studio.server.security.SignIn;
import tools.jackson.databind.json.JsonMapper;

/**
 * The first step of every live view's handshake: refuses what Spring's own handshake would refuse (not
 * a WebSocket upgrade, a foreign {@code Origin}) with a problem instead of a bare status, then takes
 * one of {@code studio.preview.max-sessions} places (503 with Retry-After when all are taken), and one of
 * its principal's ({@link PrincipalViews}: 429 with Retry-After when they have all theirs open). A
 * place taken here is given back unless the connection was upgraded, whatever later refused it: a
 * refused handshake never keeps a place.
 */
final class SessionLimit implements HandshakeInterceptor {

    static final int RETRY_AFTER_SECONDS = 5;
    private static final int SWITCHING_PROTOCOLS = 101;
    private static final String VERSION = "13";

    private final PreviewHandler handler;
    private final int maxSessions;
    private final JsonMapper json;
    private final PrincipalViews principalViews;

    SessionLimit(PreviewHandler handler, int maxSessions, JsonMapper json, PrincipalViews principalViews) {
        this.handler = handler;
        this.maxSessions = maxSessions;
        this.json = json;
        this.principalViews = principalViews;
    }

    @Override
    public boolean beforeHandshake(ServerHttpRequest request, ServerHttpResponse response, WebSocketHandler target,
                                   Map<String, Object> attributes) throws Exception {
        Refusal refusal = refusal(request);
        if (refusal != null) {
            if (refusal.status() == HttpStatus.METHOD_NOT_ALLOWED) {
                response.getHeaders().setAllow(Set.of(HttpMethod.GET));
            }
            problem(response, refusal.status(), refusal.detail());
            return false;
        }
        String principal = SignIn.principal(request.getPrincipal());
        if (!principalViews.tryOpen(principal)) {
            response.getHeaders().set(HttpHeaders.RETRY_AFTER, Integer.toString(RETRY_AFTER_SECONDS));
            problem(response, HttpStatus.TOO_MANY_REQUESTS, "you have " + principalViews.maxPerPrincipal() + " live "
                    + "views open, as many as one principal may (studio.security.max-live-views-per-principal); close "
                    + "one, or try again in " + RETRY_AFTER_SECONDS + " s");
            return false;
        }
        if (handler.tryOpen()) {
            attributes.put(PrincipalViews.PRINCIPAL, principal);
            return true;
        }
        principalViews.release(principal);
        response.getHeaders().set(HttpHeaders.RETRY_AFTER, Integer.toString(RETRY_AFTER_SECONDS));
        problem(response, HttpStatus.SERVICE_UNAVAILABLE, "this server has " + maxSessions + " live views open, as "
                + "many as it serves (studio.preview.max-sessions); try again in " + RETRY_AFTER_SECONDS + " s");
        return false;
    }

    @Override
    public void afterHandshake(ServerHttpRequest request, ServerHttpResponse response, WebSocketHandler target,
                               Exception failure) {
        // called for every handshake this interceptor let through, refused later or not
        if (failure != null || !upgraded(response)) {
            handler.release();
            principalViews.release(SignIn.principal(request.getPrincipal()));
        }
    }

    private static boolean upgraded(ServerHttpResponse response) {
        return response instanceof ServletServerHttpResponse servlet
                && servlet.getServletResponse().getStatus() == SWITCHING_PROTOCOLS;
    }

    /** Why a handshake is refused, and with which status. */
    private record Refusal(HttpStatus status, String detail) {

        static Refusal bad(String detail) {
            return new Refusal(HttpStatus.BAD_REQUEST, detail);
        }
    }

    /** Why the request is not a WebSocket handshake this server takes, or null if it is one. */
    private static Refusal refusal(ServerHttpRequest request) {
        HttpHeaders headers = request.getHeaders();
        if (!HttpMethod.GET.equals(request.getMethod())) {
            return new Refusal(HttpStatus.METHOD_NOT_ALLOWED, "the live view is a WebSocket: open it with a GET "
                    + "upgrade, not " + request.getMethod());
        }
        if (!"websocket".equalsIgnoreCase(headers.getUpgrade())) {
            return Refusal.bad("the live view is a WebSocket: the request needs the header Upgrade: websocket");
        }
        if (headers.getConnection().stream().noneMatch(token -> token.toLowerCase(Locale.ROOT).contains("upgrade"))) {
            return Refusal.bad("the live view is a WebSocket: the request needs the header Connection: Upgrade");
        }
        if (headers.getFirst("Sec-WebSocket-Key") == null) {
            return Refusal.bad("the WebSocket handshake needs the header Sec-WebSocket-Key");
        }
        if (!VERSION.equals(headers.getFirst("Sec-WebSocket-Version"))) {
            return Refusal.bad("the WebSocket handshake needs the header Sec-WebSocket-Version: " + VERSION);
        }
        if (!WebUtils.isSameOrigin(request)) {
            return new Refusal(HttpStatus.FORBIDDEN, "a live view is opened only by pages this server serves, "
                    + "and the request's Origin is another site's");
        }
        return null;
    }

    private void problem(ServerHttpResponse response, HttpStatus status, String detail) throws java.io.IOException {
        Map<String, Object> problem = new LinkedHashMap<>();
        problem.put("type", "about:blank");
        problem.put("title", status.getReasonPhrase());
        problem.put("status", status.value());
        problem.put("detail", detail);
        problem.put("instance", "/api/preview");
        response.setStatusCode(status);
        response.getHeaders().setContentType(MediaType.APPLICATION_PROBLEM_JSON);
        response.getBody().write(json.writeValueAsBytes(problem));
    }
}

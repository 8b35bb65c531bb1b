package studio.server.system;

import org.apache.coyote.ActionCode;
import org.apache.coyote.ContinueResponseTiming;

import jakarta.servlet.http.HttpServletRequest;

/**
 * Sends "100 Continue" to a client that asked for it ({@code Expect: 100-continue}) before its body
 * is read in the background. Tomcat sends it on the first blocking read (the service sets the
 * timing "on read", so that a body over the limit is refused without an invitation), but never for
 * a body read with a read listener, whose client would wait for an invitation that does not come.
 * With another container nothing is sent.
 */
final class ContinueInvitation {

    private ContinueInvitation() {
    }

    static void sendIfExpected(HttpServletRequest request) {
        if (!"100-continue".equalsIgnoreCase(request.getHeader("Expect"))) {
            return;
        }
        org.apache.coyote.Request coyote = TomcatRequests.coyote(request);
        if (coyote == null) {
            return;
        }
        try {
            coyote.action(ActionCode.ACK, ContinueResponseTiming.ON_REQUEST_BODY_READ);
        } catch (RuntimeException e) {
            // the client sends its body after a while anyway (RFC 9110 section 10.1.1)
        }
    }
}

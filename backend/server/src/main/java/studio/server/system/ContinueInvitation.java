package studio.server.system;

import java.lang.reflect.Field;

import org.apache.catalina.connector.RequestFacade;
import org.apache.coyote.ActionCode;
import org.apache.coyote.ContinueResponseTiming;

import jakarta.servlet.ServletRequest;
import jakarta.servlet.ServletRequestWrapper;

/**
 * Sends "100 Continue" to a client that asked for it ({@code Expect: 100-continue}) before its body
 * is read in the background. Tomcat sends it on the first blocking read (the service sets the
 * timing "on read", so that a body over the limit is refused without an invitation), but never for
 * a body read with a read listener, whose client would wait for an invitation that does not come.
 * Tomcat's request is reached by reflection, as {@code ClientProbe} does; with another container
 * nothing is sent.
 */
final class ContinueInvitation {

    private static final Field FACADE_REQUEST = facadeRequestField();

    private ContinueInvitation() {
    }

    static void sendIfExpected(ServletRequest request) {
        if (!(request instanceof jakarta.servlet.http.HttpServletRequest http)
                || !"100-continue".equalsIgnoreCase(http.getHeader("Expect"))) {
            return;
        }
        ServletRequest inner = request;
        while (inner instanceof ServletRequestWrapper wrapper) {
            inner = wrapper.getRequest();
        }
        if (FACADE_REQUEST == null || !(inner instanceof RequestFacade)) {
            return;
        }
        try {
            var connector = (org.apache.catalina.connector.Request) FACADE_REQUEST.get(inner);
            if (connector != null) {
                connector.getCoyoteRequest().action(ActionCode.ACK, ContinueResponseTiming.ON_REQUEST_BODY_READ);
            }
        } catch (ReflectiveOperationException | RuntimeException e) {
            // the client sends its body after a while anyway (RFC 9110 section 10.1.1)
        }
    }

    private static Field facadeRequestField() {
        try {
            Field field = RequestFacade.class.getDeclaredField("request");
            field.setAccessible(true);
            return field;
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            return null;
        }
    }
}

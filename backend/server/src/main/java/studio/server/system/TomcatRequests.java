package studio.server.system;

import java.lang.reflect.Field;

import org.apache.catalina.connector.RequestFacade;

import jakarta.servlet.ServletRequest;
import jakarta.servlet.ServletRequestWrapper;

/**
 * Tomcat's own request behind a servlet request, for what the servlet API cannot do (probe the
 * connection, send "100 Continue" on demand). It is reached by reflection; with another container,
 * or if Tomcat's fields change, there is none and the callers do without.
 */
public final class TomcatRequests {

    private static final Field FACADE_REQUEST = facadeRequestField();

    private TomcatRequests() {
    }

    /** Tomcat's coyote request behind {@code request} (unwrapping wrappers), or null. */
    public static org.apache.coyote.Request coyote(ServletRequest request) {
        ServletRequest inner = request;
        while (inner instanceof ServletRequestWrapper wrapper) {
            inner = wrapper.getRequest();
        }
        if (FACADE_REQUEST == null || !(inner instanceof RequestFacade)) {
            return null;
        }
        try {
            var connector = (org.apache.catalina.connector.Request) FACADE_REQUEST.get(inner);
            return connector != null ? connector.getCoyoteRequest() : null;
        } catch (ReflectiveOperationException | RuntimeException e) {
            return null;
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

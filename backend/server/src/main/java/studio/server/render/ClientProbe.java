package studio.server.render;

import org.apache.coyote.ActionCode;

import jakarta.servlet.ServletRequest;
import studio.server.system.TomcatRequests;

/**
 * Whether the client of a waiting request has gone away. The servlet API cannot tell: Tomcat
 * reports a closed connection only when the response is written, and a synchronous render writes
 * nothing until its image is done. So the probe asks Tomcat's connector for a non-blocking read of
 * the connection (its "available" action with reading allowed): once the request body has been read,
 * a connection that has something to read has been closed or reset by the client (a client waiting
 * for its image sends nothing more). Reads are rate-limited and serialised, and the probe is closed
 * before the request completes, so it never touches a connection the container has recycled. With
 * another container it answers "still there", and only a failed write notices. A client that
 * half-closes its side of the connection after the body (rare: HTTP clients keep it open for the
 * response) looks gone too, and so does one that pipelines its next request behind this one.
 */
public final class ClientProbe {

    /** The probe when the container is not Tomcat, and in tests: the client is always there. */
    public static final ClientProbe NONE = new ClientProbe(null);

    /** At most one read of the connection per this many nanoseconds. */
    private static final long MIN_INTERVAL_NANOS = 20_000_000;

    private final org.apache.coyote.Request coyote;
    private boolean closed, gone;
    private long lastProbe;

    private ClientProbe(org.apache.coyote.Request coyote) {
        this.coyote = coyote;
        this.closed = coyote == null;
    }

    /** A probe of the request's connection, or {@link #NONE} if it cannot be probed. */
    public static ClientProbe of(ServletRequest request) {
        org.apache.coyote.Request coyote = TomcatRequests.coyote(request);
        return coyote != null ? new ClientProbe(coyote) : NONE;
    }

    /** True once the client has closed or reset the connection. */
    public synchronized boolean gone() {
        if (closed || gone) {
            return gone;
        }
        long now = System.nanoTime();
        if (now - lastProbe < MIN_INTERVAL_NANOS) {
            return false;
        }
        lastProbe = now;
        try {
            coyote.action(ActionCode.AVAILABLE, Boolean.TRUE);
            gone = coyote.getAvailable() > 0;
        } catch (RuntimeException e) {
            gone = true;
        }
        return gone;
    }

    /** Stops probing: the request is completing and its connection may soon serve another. */
    public synchronized void close() {
        closed = true;
    }
}

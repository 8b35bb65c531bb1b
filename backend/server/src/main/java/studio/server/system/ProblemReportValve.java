package studio.server.system;

import java.io.IOException;
import java.io.PrintWriter;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicBoolean;

import org.apache.catalina.connector.Request;
import org.apache.catalina.connector.Response;
import org.apache.catalina.valves.ErrorReportValve;
import org.apache.coyote.ActionCode;
import org.apache.coyote.ProtocolHandler;
import org.apache.coyote.http11.AbstractHttp11Protocol;
import org.apache.tomcat.util.res.StringManager;

import tools.jackson.core.json.JsonWriteFeature;
import tools.jackson.databind.json.JsonMapper;

/**
 * Tomcat's error report as an RFC 9457 problem instead of its HTML page. It answers the requests
 * the container refuses before any servlet runs, so that no error page of the application can:
 * a request line, path or header it cannot parse (a NUL, an encoded '/' or a bad %-escape in the
 * path, a header over the size limit), an HTTP version or Transfer-Encoding it does not speak, a
 * bad Expect. Errors that reach the application go to /error ({@link ProblemErrorController}) as
 * before; this writes only when nothing has been written yet. Installed on the Host in place of
 * Tomcat's ErrorReportValve ({@link TomcatSetup}).
 */
final class ProblemReportValve extends ErrorReportValve {

    static final String PROBLEM_JSON = "application/problem+json";

    /** Tomcat's message for a request line and headers over maxHttpRequestHeaderSize, in its locale. */
    private static final String HEADER_TOO_LARGE = StringManager.getManager("org.apache.coyote.http11")
            .getString("iib.requestheadertoolarge.error");

    /** ASCII only: the reporter writes in the response's default charset, ISO-8859-1. */
    private static final JsonMapper JSON = JsonMapper.builder().enable(JsonWriteFeature.ESCAPE_NON_ASCII).build();

    @Override
    protected void report(Request request, Response response, Throwable thrown) {
        int status = response.getStatus();
        if (status < 400 || response.getContentWritten() > 0 || !response.setErrorReported()) {
            return;
        }
        AtomicBoolean ioAllowed = new AtomicBoolean();
        response.getCoyoteResponse().action(ActionCode.IS_IO_ALLOWED, ioAllowed);
        if (!ioAllowed.get()) {
            return;
        }
        Map<String, Object> problem = new LinkedHashMap<>();
        problem.put("title", StatusDetails.title(status));
        problem.put("status", status);
        problem.put("detail", detail(status, thrown, response.getMessage(), maxHeaderBytes(request)));
        try {
            response.setContentType(PROBLEM_JSON);
            PrintWriter writer = response.getReporter();
            if (writer != null) {
                writer.write(JSON.writeValueAsString(problem));
                response.finishResponse();
            }
        } catch (IOException | IllegalStateException e) {
            // the client has gone, or the response cannot take a body any more: nobody to tell
        }
    }

    /**
     * Tomcat answers 400 for three kinds of request it cannot take, and tells them apart only so
     * far: one whose request line or headers it cannot parse (it throws, and says so when they are
     * too long); one whose path it cannot decode or normalise (it sends the error with a message of
     * its own); and, with a bare status, one whose path does not decode as UTF-8 or whose Host,
     * Content-Length or Transfer-Encoding it cannot take.
     */
    static String detail(int status, Throwable thrown, String message, int maxHeaderBytes) {
        if (status != 400) {
            return StatusDetails.detail(status);
        }
        if (thrown != null && HEADER_TOO_LARGE.equals(thrown.getMessage())) {
            return "the request line and headers are longer than this server's limit of " + maxHeaderBytes
                    + " bytes (server.max-http-request-header-size): send a shorter URL or smaller headers";
        }
        if (thrown != null) {
            return "the request line or a header cannot be read: it holds a character HTTP does not allow there";
        }
        if (message != null) {
            return "the path cannot be read: it holds a malformed %-escape, an encoded NUL (%00), '/' (%2F) or "
                    + "'\\' (%5C), a backslash, or a '..' that climbs above the root";
        }
        return "the request cannot be taken as it is: a path that does not decode, or a missing or repeated Host, "
                + "or a malformed Content-Length or Transfer-Encoding";
    }

    private static int maxHeaderBytes(Request request) {
        ProtocolHandler protocol = request.getConnector() != null ? request.getConnector().getProtocolHandler() : null;
        return protocol instanceof AbstractHttp11Protocol<?> http ? http.getMaxHttpRequestHeaderSize() : 8192;
    }
}

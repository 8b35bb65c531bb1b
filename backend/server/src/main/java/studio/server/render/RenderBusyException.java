package studio.server.render;

import org.springframework.http.HttpHeaders;
import org.springframework.http.HttpStatus;
import org.springframework.http.ProblemDetail;
import org.springframework.web.ErrorResponseException;

/**
 * Every render slot, or the memory a render needs, is taken, the server is stopping, or it gave up
 * waiting for a render; the client should retry later: 503 with Retry-After.
 */
public final class RenderBusyException extends ErrorResponseException {

    static final int RETRY_AFTER_SECONDS = 5;

    public RenderBusyException() {
        this("the server is busy rendering other scenes; try again shortly");
    }

    public RenderBusyException(String message) {
        super(HttpStatus.SERVICE_UNAVAILABLE, ProblemDetail.forStatusAndDetail(HttpStatus.SERVICE_UNAVAILABLE,
                message), null);
        getHeaders().set(HttpHeaders.RETRY_AFTER, Integer.toString(RETRY_AFTER_SECONDS));
    }

    /** The problem's detail. */
    @Override
    public String getMessage() {
        return getBody().getDetail();
    }
}

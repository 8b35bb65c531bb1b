package studio.server.system;

import org.springframework.http.HttpHeaders;
import org.springframework.http.HttpStatus;
import org.springframework.http.ProblemDetail;
import org.springframework.web.ErrorResponseException;

/** The memory a request needs to be read and compiled is held by other work right now: 503 with Retry-After. */
public final class MemoryBusyException extends ErrorResponseException {

    static final int RETRY_AFTER_SECONDS = 2;

    public MemoryBusyException() {
        super(HttpStatus.SERVICE_UNAVAILABLE, ProblemDetail.forStatusAndDetail(HttpStatus.SERVICE_UNAVAILABLE,
                "the server is reading or rendering as much as its memory allows; try again in " + RETRY_AFTER_SECONDS
                        + " s"), null);
        getHeaders().set(HttpHeaders.RETRY_AFTER, Integer.toString(RETRY_AFTER_SECONDS));
    }
}

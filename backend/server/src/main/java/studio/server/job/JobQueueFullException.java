package studio.server.job;

import org.springframework.http.HttpHeaders;
import org.springframework.http.HttpStatus;
import org.springframework.http.ProblemDetail;
import org.springframework.web.ErrorResponseException;

/** Every render slot and queue place, or the render memory, is taken: 429 with Retry-After. */
public final class JobQueueFullException extends ErrorResponseException {

    private final int retryAfterSeconds;

    public JobQueueFullException(int retryAfterSeconds) {
        this(retryAfterSeconds, "the render queue is full");
    }

    /** @param why what is full, e.g. "the render queue is full" */
    public JobQueueFullException(int retryAfterSeconds, String why) {
        super(HttpStatus.TOO_MANY_REQUESTS, ProblemDetail.forStatusAndDetail(HttpStatus.TOO_MANY_REQUESTS,
                why + "; try again in " + retryAfterSeconds + " s"), null);
        getHeaders().set(HttpHeaders.RETRY_AFTER, Integer.toString(retryAfterSeconds));
        this.retryAfterSeconds = retryAfterSeconds;
    }

    public int retryAfterSeconds() {
        return retryAfterSeconds;
    }

    /** The problem's detail. */
    @Override
    public String getMessage() {
        return getBody().getDetail();
    }
}

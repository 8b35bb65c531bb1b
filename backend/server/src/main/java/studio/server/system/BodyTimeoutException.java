package studio.server.system;

import org.springframework.http.HttpStatus;
import org.springframework.http.ProblemDetail;
import org.springframework.web.ErrorResponseException;

/** A request body that arrives too slowly: 408. */
public final class BodyTimeoutException extends ErrorResponseException {

    public BodyTimeoutException(String detail) {
        super(HttpStatus.REQUEST_TIMEOUT, ProblemDetail.forStatusAndDetail(HttpStatus.REQUEST_TIMEOUT, detail), null);
    }
}

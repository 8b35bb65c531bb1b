package studio.server.job;

import org.springframework.http.HttpStatus;
import org.springframework.http.ProblemDetail;
import org.springframework.web.ErrorResponseException;

/** No job has that id (it never existed, or it expired): 404. */
public final class JobNotFoundException extends ErrorResponseException {

    public JobNotFoundException(String id) {
        super(HttpStatus.NOT_FOUND, ProblemDetail.forStatusAndDetail(HttpStatus.NOT_FOUND, "no render job '"
                + id.replaceAll("[^A-Za-z0-9-]", "") + "'; it never existed or has expired"), null);
    }

    /** The problem's detail. */
    @Override
    public String getMessage() {
        return getBody().getDetail();
    }
}

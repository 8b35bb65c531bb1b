package studio.server.job;

import org.springframework.http.HttpStatus;
import org.springframework.http.ProblemDetail;
import org.springframework.web.ErrorResponseException;

/** The job's image was asked for before the job was done (or after it failed or was cancelled): 409. */
public final class JobNotDoneException extends ErrorResponseException {

    public JobNotDoneException(String id, JobState state) {
        super(HttpStatus.CONFLICT, ProblemDetail.forStatusAndDetail(HttpStatus.CONFLICT, "render job " + id + " is "
                + state.json() + "; its image exists only once it is done"), null);
    }

    /** The problem's detail. */
    @Override
    public String getMessage() {
        return getBody().getDetail();
    }
}

package studio.server.render;

import java.time.Duration;

import org.springframework.http.HttpStatus;
import org.springframework.http.ProblemDetail;
import org.springframework.web.ErrorResponseException;

/** A render ran longer than this server's time budget per render and was stopped: 422. */
public final class RenderTimeExceededException extends ErrorResponseException {

    public RenderTimeExceededException(Duration budget) {
        super(HttpStatus.UNPROCESSABLE_CONTENT, problem(budget), null);
    }

    private static ProblemDetail problem(Duration budget) {
        ProblemDetail problem = ProblemDetail.forStatusAndDetail(HttpStatus.UNPROCESSABLE_CONTENT, "the render was "
                + "stopped after " + RenderBudget.describe(budget) + ", this server's time budget per render "
                + "(studio.limits.max-render-time); lower render.samples, the image size or render.maxDepth");
        problem.setTitle("Render time budget exceeded");
        return problem;
    }

    /** The problem's detail (a job that ran out of time keeps it as its error). */
    @Override
    public String getMessage() {
        return getBody().getDetail();
    }
}

package studio.server.system;

import java.util.stream.Collectors;

import org.apache.tomcat.util.http.InvalidParameterException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.springframework.http.HttpHeaders;
import org.springframework.http.HttpStatus;
import org.springframework.http.HttpStatusCode;
import org.springframework.http.MediaType;
import org.springframework.http.ProblemDetail;
import org.springframework.http.ResponseEntity;
import org.springframework.http.converter.HttpMessageNotReadableException;
import org.springframework.web.HttpMediaTypeNotSupportedException;
import org.springframework.web.bind.annotation.ExceptionHandler;
import org.springframework.web.bind.annotation.RestControllerAdvice;
import org.springframework.web.context.request.WebRequest;
import org.springframework.web.servlet.mvc.method.annotation.ResponseEntityExceptionHandler;
import org.springframework.web.servlet.resource.NoResourceFoundException;

import studio.engine.render.RenderCancelledException;
import studio.server.job.JobNotDoneException;
import studio.server.job.JobNotFoundException;
import studio.server.job.JobQueueFullException;
import studio.server.render.RenderBusyException;
import studio.server.render.RenderTimeExceededException;
import studio.server.scene.format.InvalidSceneException;

/**
 * Every error as an RFC 9457 problem (application/problem+json). An invalid scene is a 400 whose
 * {@code errors} property lists each bad field by its JSON path and why.
 */
@RestControllerAdvice
class ProblemAdvice extends ResponseEntityExceptionHandler {

    private static final Logger log = LoggerFactory.getLogger(ProblemAdvice.class);

    @ExceptionHandler(InvalidSceneException.class)
    ResponseEntity<ProblemDetail> invalidScene(InvalidSceneException e) {
        return ResponseEntity.badRequest().body(Problems.invalidScene(e));
    }

    @ExceptionHandler(JobNotFoundException.class)
    ResponseEntity<ProblemDetail> jobNotFound(JobNotFoundException e) {
        return ResponseEntity.status(HttpStatus.NOT_FOUND)
                .body(ProblemDetail.forStatusAndDetail(HttpStatus.NOT_FOUND, e.getMessage()));
    }

    @ExceptionHandler(JobNotDoneException.class)
    ResponseEntity<ProblemDetail> jobNotDone(JobNotDoneException e) {
        return ResponseEntity.status(HttpStatus.CONFLICT)
                .body(ProblemDetail.forStatusAndDetail(HttpStatus.CONFLICT, e.getMessage()));
    }

    @ExceptionHandler(JobQueueFullException.class)
    ResponseEntity<ProblemDetail> queueFull(JobQueueFullException e) {
        return ResponseEntity.status(HttpStatus.TOO_MANY_REQUESTS)
                .header(HttpHeaders.RETRY_AFTER, Integer.toString(e.retryAfterSeconds()))
                .body(ProblemDetail.forStatusAndDetail(HttpStatus.TOO_MANY_REQUESTS, e.getMessage()));
    }

    @ExceptionHandler(BodyTooLargeException.class)
    ResponseEntity<ProblemDetail> bodyTooLarge(BodyTooLargeException e) {
        ProblemDetail problem = ProblemDetail.forStatusAndDetail(HttpStatus.CONTENT_TOO_LARGE, e.getMessage());
        return ResponseEntity.status(HttpStatus.CONTENT_TOO_LARGE).body(problem);
    }

    @ExceptionHandler(RenderBusyException.class)
    ResponseEntity<ProblemDetail> busy(RenderBusyException e) {
        ProblemDetail problem = ProblemDetail.forStatusAndDetail(HttpStatus.SERVICE_UNAVAILABLE, e.getMessage());
        return ResponseEntity.status(HttpStatus.SERVICE_UNAVAILABLE).header(HttpHeaders.RETRY_AFTER, "5").body(problem);
    }

    @ExceptionHandler(RenderTimeExceededException.class)
    ResponseEntity<ProblemDetail> renderTooLong(RenderTimeExceededException e) {
        ProblemDetail problem = ProblemDetail.forStatusAndDetail(HttpStatus.UNPROCESSABLE_CONTENT, e.getMessage());
        problem.setTitle("Render time budget exceeded");
        return ResponseEntity.status(HttpStatus.UNPROCESSABLE_CONTENT).body(problem);
    }

    /** Only a client that is still there sees this: its render was stopped because the server is stopping. */
    @ExceptionHandler(RenderCancelledException.class)
    ResponseEntity<ProblemDetail> renderCancelled(RenderCancelledException e) {
        ProblemDetail problem = ProblemDetail.forStatusAndDetail(HttpStatus.SERVICE_UNAVAILABLE,
                "the render was cancelled before it finished (the server is shutting down); try again shortly");
        return ResponseEntity.status(HttpStatus.SERVICE_UNAVAILABLE).header(HttpHeaders.RETRY_AFTER, "5").body(problem);
    }

    /** Tomcat cannot read the query string: a parameter without a name, a bad %-escape, too many parameters. */
    @ExceptionHandler(InvalidParameterException.class)
    ResponseEntity<ProblemDetail> unreadableParameters(InvalidParameterException e) {
        HttpStatus status = HttpStatus.resolve(e.getErrorCode());
        if (status == null || !status.is4xxClientError()) {
            status = HttpStatus.BAD_REQUEST;
        }
        return ResponseEntity.status(status).body(ProblemDetail.forStatusAndDetail(status, "the request's parameters "
                + "cannot be read: a parameter without a name, a malformed %-escape, or too many parameters"));
    }

    @Override
    protected ResponseEntity<Object> handleHttpMessageNotReadable(HttpMessageNotReadableException e, HttpHeaders headers,
            HttpStatusCode status, WebRequest request) {
        Throwable cause = e.getMostSpecificCause();
        if (cause instanceof BodyTooLargeException tooLarge) {
            return ResponseEntity.status(HttpStatus.CONTENT_TOO_LARGE)
                    .body(ProblemDetail.forStatusAndDetail(HttpStatus.CONTENT_TOO_LARGE, tooLarge.getMessage()));
        }
        return super.handleHttpMessageNotReadable(e, headers, status, request);
    }

    /** A scene posted as anything but JSON (see SceneMediaTypes): say what to send, and what was sent. */
    @Override
    protected ResponseEntity<Object> handleHttpMediaTypeNotSupported(HttpMediaTypeNotSupportedException e,
            HttpHeaders headers, HttpStatusCode status, WebRequest request) {
        String accepted = e.getSupportedMediaTypes().stream().map(MediaType::toString).collect(Collectors.joining(" or "));
        String given = request.getHeader(HttpHeaders.CONTENT_TYPE);
        String detail = (accepted.isEmpty() ? "the body's media type is not accepted here"
                : "the body must be sent as " + accepted + " (Content-Type: " + e.getSupportedMediaTypes().get(0) + ")")
                + (given == null || given.isBlank() ? "; this request has no Content-Type"
                : e.getContentType() == null ? "; this request's, '" + abbreviated(given) + "', cannot be read (a "
                + "malformed type, or a charset this server does not know)"
                : "; this request's is '" + abbreviated(given) + "'");
        return handleExceptionInternal(e, ProblemDetail.forStatusAndDetail(status, detail), headers, status, request);
    }

    /** Spring's own detail ("No static resource api/x.") speaks of its resource handling. */
    @Override
    protected ResponseEntity<Object> handleNoResourceFoundException(NoResourceFoundException e, HttpHeaders headers,
            HttpStatusCode status, WebRequest request) {
        ProblemDetail problem = ProblemDetail.forStatusAndDetail(status, "there is nothing at /"
                + abbreviated(e.getResourcePath()));
        return handleExceptionInternal(e, problem, headers, status, request);
    }

    /** Text from the request, cut short for the detail that repeats it. */
    private static String abbreviated(String text) {
        return text.length() > 100 ? text.substring(0, 100) + "…" : text;
    }

    @ExceptionHandler(Exception.class)
    ResponseEntity<ProblemDetail> unexpected(Exception e) {
        log.error("unexpected error", e);
        ProblemDetail problem = ProblemDetail.forStatusAndDetail(HttpStatus.INTERNAL_SERVER_ERROR,
                "an unexpected error occurred; it has been logged");
        return ResponseEntity.internalServerError().body(problem);
    }
}

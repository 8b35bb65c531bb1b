package studio.server.system;

import org.springframework.http.HttpStatus;
import org.springframework.http.ProblemDetail;
import org.springframework.web.ErrorResponseException;

/** Reading and compiling a request's scene needs more than the whole memory budget: 413, as retrying cannot help. */
public final class MemoryExceededException extends ErrorResponseException {

    public MemoryExceededException(long capacity) {
        super(HttpStatus.CONTENT_TOO_LARGE, ProblemDetail.forStatusAndDetail(HttpStatus.CONTENT_TOO_LARGE,
                "this scene needs more than all of this server's " + mebibytes(capacity) + " MiB of render memory "
                        + "(studio.render-memory) to be read and its meshes built; send a smaller scene or smaller "
                        + "meshes"), null);
    }

    private static long mebibytes(long bytes) {
        return (bytes + (1L << 20) - 1) >> 20;
    }
}

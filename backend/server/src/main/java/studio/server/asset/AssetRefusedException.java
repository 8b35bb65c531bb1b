package studio.server.asset;

import org.springframework.http.HttpHeaders;
import org.springframework.http.HttpStatus;
import org.springframework.http.ProblemDetail;
import org.springframework.web.ErrorResponseException;

/** Why an asset is not kept or not found, as its RFC 9457 problem; nothing of a refused upload is kept. */
final class AssetRefusedException extends ErrorResponseException {

    /** How long a client is told to wait when the store is full of what other work holds. */
    static final int RETRY_AFTER_SECONDS = 5;

    private AssetRefusedException(HttpStatus status, String title, String detail) {
        super(status, problem(status, title, detail), null);
    }

    private static ProblemDetail problem(HttpStatus status, String title, String detail) {
        ProblemDetail problem = ProblemDetail.forStatusAndDetail(status, detail);
        problem.setTitle(title);
        return problem;
    }

    /** 400 "Invalid asset": the bytes are not what their media type says, or break a limit of their kind. */
    static AssetRefusedException invalid(AssetType type, String why) {
        return new AssetRefusedException(HttpStatus.BAD_REQUEST, "Invalid asset",
                "the body is not a usable " + type.mediaType() + " asset: " + why);
    }

    static AssetRefusedException unsupported(String contentType) {
        return new AssetRefusedException(HttpStatus.UNSUPPORTED_MEDIA_TYPE, "Unsupported Media Type",
                "an asset must be sent as model/obj, image/png, image/jpeg, model/gltf-binary or model/gltf+json "
                        + "(its Content-Type); this request's is " + (contentType == null || contentType.isBlank()
                        ? "missing" : "'" + (contentType.length() > 100 ? contentType.substring(0, 100) + "…"
                        : contentType) + "'"));
    }

    static AssetRefusedException tooLarge(long bytes, long max) {
        return new AssetRefusedException(HttpStatus.CONTENT_TOO_LARGE, "Content Too Large",
                "the asset is " + bytes + " bytes; this server keeps assets of at most " + max
                        + " bytes (studio.assets.max-bytes)");
    }

    /** 503 with Retry-After: the store cannot make room now (the memory is held by renders). */
    static AssetRefusedException full(long bytes) {
        AssetRefusedException e = new AssetRefusedException(HttpStatus.SERVICE_UNAVAILABLE, "Service Unavailable",
                "the server has no room for an asset of " + bytes + " bytes now (its memory is held by other "
                        + "work); try again in " + RETRY_AFTER_SECONDS + " s");
        e.getHeaders().set(HttpHeaders.RETRY_AFTER, Integer.toString(RETRY_AFTER_SECONDS));
        return e;
    }

    static AssetRefusedException badId() {
        return new AssetRefusedException(HttpStatus.BAD_REQUEST, "Bad Request",
                "an asset id is \"sha256-\" and 64 lowercase hex digits");
    }

    static AssetRefusedException notFound(String id) {
        return new AssetRefusedException(HttpStatus.NOT_FOUND, "Not Found", "this server has no asset " + id
                + "; upload it with POST /api/assets");
    }
}

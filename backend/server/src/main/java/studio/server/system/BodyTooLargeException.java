package studio.server.system;

/** A request body larger than the configured limit. */
public final class BodyTooLargeException extends RuntimeException {

    public BodyTooLargeException(long limit) {
        super("the request body is larger than this server's limit of " + limit + " bytes");
    }
}

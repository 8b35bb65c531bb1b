package studio.server.job;

/** Every render slot and queue place is taken. */
public final class JobQueueFullException extends RuntimeException {

    private final int retryAfterSeconds;

    public JobQueueFullException(int retryAfterSeconds) {
        super("the render queue is full; try again in " + retryAfterSeconds + " s");
        this.retryAfterSeconds = retryAfterSeconds;
    }

    public int retryAfterSeconds() {
        return retryAfterSeconds;
    }
}

package studio.server.job;

/** Every render slot and queue place, or the render memory, is taken. */
public final class JobQueueFullException extends RuntimeException {

    private final int retryAfterSeconds;

    public JobQueueFullException(int retryAfterSeconds) {
        this(retryAfterSeconds, "the render queue is full");
    }

    /** @param why what is full, e.g. "the render queue is full" */
    public JobQueueFullException(int retryAfterSeconds, String why) {
        super(why + "; try again in " + retryAfterSeconds + " s");
        this.retryAfterSeconds = retryAfterSeconds;
    }

    public int retryAfterSeconds() {
        return retryAfterSeconds;
    }
}

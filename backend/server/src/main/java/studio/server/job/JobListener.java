package studio.server.job;

/**
 * Hears one job's events, in order, on a thread of the job service's sender pool: never on a render
 * thread and never with the job's lock held, so a listener may write to a slow connection.
 */
public interface JobListener {

    void status(JobStatus status);

    void tile(TileEvent tile);

    /** The job reached a final state; nothing follows. */
    void end(JobStatus status);

    /** Nothing happened for a while; a listener with a connection may check it is still open. */
    default void heartbeat() {
    }

    /**
     * The listener fell behind (a delivery did not return for {@link JobService#STALL_MILLIS}) and was
     * dropped: nothing follows, and the job goes on without it.
     */
    default void dropped() {
    }
}

package studio.server.job;

/** Hears one job's events; called with the job's lock held, in order. */
interface JobListener {

    void status(JobStatus status);

    void tile(TileEvent tile);

    /** The job reached a final state; nothing follows. */
    void end(JobStatus status);

    /** Nothing happened for a while; a listener with a connection may check it is still open. */
    default void heartbeat() {
    }
}

package studio.server.job;

/**
 * Who submits a job, and how many of their jobs may be queued or running at once on this member.
 * With sign-in off every job belongs to {@link #ANYONE}: whoever knows a job's id may watch, fetch
 * and cancel it, as before sign-in existed.
 *
 * @param principal the signed-in principal's name, "" with sign-in off
 * @param maxJobs   the most of this principal's jobs queued or running here at once; one more gets 429
 */
public record JobOwner(String principal, int maxJobs) {

    /** With sign-in off: every caller is the same nobody, limited only by the queue. */
    public static final JobOwner ANYONE = new JobOwner("", Integer.MAX_VALUE);

    public JobOwner {
        if (principal == null) {
            throw new IllegalArgumentException("a job's principal is \"\" with sign-in off, never null");
        }
        if (maxJobs < 1) {
            throw new IllegalArgumentException("maxJobs must be at least 1");
        }
    }
}

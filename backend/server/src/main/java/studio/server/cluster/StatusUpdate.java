package studio.server.cluster;

import java.util.function.UnaryOperator;

import studio.server.job.JobStatus;

/**
 * Writes a job's status to the job table ({@link SealedMap#update}, compare-and-set), unless the job
 * ended there already or another member owns it now: a status written late (a tile's progress that
 * reaches the table after the end) never takes the end back, and a member that was taken for dead,
 * or handed its job over, does not overwrite its job's new owner.
 */
record StatusUpdate(String owner, JobStatus status) implements UnaryOperator<JobRecord> {

    /** The job with the status, or null to leave it. */
    @Override
    public JobRecord apply(JobRecord job) {
        if (!job.owner().equals(owner) || job.status().state().isFinal()) {
            return null;
        }
        return job.withStatus(status);
    }
}

package studio.server.cluster;

import studio.server.job.JobStatus;

/**
 * A job in the cluster's job table (written as {@link ClusterCodecs#JOB_RECORD}).
 *
 * @param owner     the id of the member that runs the job (accepted it, or took it over); empty
 *                  while a stopping member hands it to the others
 * @param tileSize  the job's tiling, fixed when it was accepted, so that a member that takes it over
 *                  cuts the same tiles
 * @param principal who submitted the job; empty when sign-in is off
 */
record JobRecord(JobStatus status, String owner, int tileSize, String principal) {

    JobRecord withStatus(JobStatus next) {
        return new JobRecord(next, owner, tileSize, principal);
    }

    /** Whether {@code caller} may see the job: to anyone else the cluster knows no such job. */
    boolean belongsTo(String caller) {
        return principal.equals(caller);
    }

    JobRecord withOwner(String next) {
        return new JobRecord(status, next, tileSize, principal);
    }
}

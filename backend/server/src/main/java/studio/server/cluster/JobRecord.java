package studio.server.cluster;

import java.io.Serializable;

import studio.server.job.JobStatus;

/**
 * A job in the cluster's job table.
 *
 * @param owner    the id of the member that runs the job (accepted it, or took it over)
 * @param tileSize the job's tiling, fixed when it was accepted, so that a member that takes it over
 *                 cuts the same tiles
 * @param principal who submitted the job ("" with sign-in off): every member serves the job to them only
 */
record JobRecord(JobStatus status, String owner, int tileSize, String principal) implements Serializable {

    JobRecord withStatus(JobStatus next) {
        return new JobRecord(next, owner, tileSize, principal);
    }

    /** Whether {@code caller} may see the job: to anyone else the cluster knows no such job. */
    boolean belongsTo(String caller) {
        return principal.equals(caller);
    }
}

package studio.server.cluster;

import java.io.Serializable;

import studio.server.job.JobStatus;

/**
 * A job in the cluster's job table.
 *
 * @param owner    the id of the member that runs the job (accepted it, or took it over)
 * @param tileSize the job's tiling, fixed when it was accepted, so that a member that takes it over
 *                 cuts the same tiles
 */
record JobRecord(JobStatus status, String owner, int tileSize) implements Serializable {

    JobRecord withStatus(JobStatus next) {
        return new JobRecord(next, owner, tileSize);
    }
}

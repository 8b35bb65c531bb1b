package studio.server.cluster;

import java.util.Map;

import com.hazelcast.map.EntryProcessor;

import studio.server.job.JobStatus;

/**
 * Writes a job's status to the job table, on the member that holds the job's entry, unless the job
 * ended there already or another member owns it now: a status written late (a tile's progress that
 * reaches the table after the end) never takes the end back, and a member that was taken for dead
 * does not overwrite its job's new owner.
 *
 * @return true if the status was written
 */
record StatusUpdate(String owner, JobStatus status) implements EntryProcessor<String, JobRecord, Boolean> {

    @Override
    public Boolean process(Map.Entry<String, JobRecord> entry) {
        JobRecord job = entry.getValue();
        if (job == null || !job.owner().equals(owner) || job.status().state().isFinal()) {
            return false;
        }
        entry.setValue(job.withStatus(status));
        return true;
    }
}

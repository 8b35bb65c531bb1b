package studio.server.cluster;

import java.util.Map;

import com.hazelcast.map.EntryProcessor;

/**
 * Moves an unfinished job from a member that left to the member that asks, on the member that holds
 * the job's entry: of all the members that try at once, exactly one gets true.
 */
record TakeOver(String from, String to) implements EntryProcessor<String, JobRecord, Boolean> {

    @Override
    public Boolean process(Map.Entry<String, JobRecord> entry) {
        JobRecord job = entry.getValue();
        if (job == null || !job.owner().equals(from) || job.status().state().isFinal()) {
            return false;
        }
        entry.setValue(new JobRecord(job.status(), to, job.tileSize(), job.principal()));
        return true;
    }
}

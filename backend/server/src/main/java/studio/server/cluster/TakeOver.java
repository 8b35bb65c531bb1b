package studio.server.cluster;

import java.util.function.UnaryOperator;

/**
 * Moves an unfinished job from a member that left (or handed it over) to the member that asks, by
 * compare-and-set on the job's entry ({@link SealedMap#update}): of all the members that try at once,
 * exactly one succeeds.
 */
record TakeOver(String from, String to) implements UnaryOperator<JobRecord> {

    /** The job owned by {@code to}, or null to leave it. */
    @Override
    public JobRecord apply(JobRecord job) {
        if (!job.owner().equals(from) || job.status().state().isFinal()) {
            return null;
        }
        return job.withOwner(to);
    }
}

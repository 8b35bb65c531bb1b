package studio.server.job;

/** The job's image was asked for before the job was done (or after it failed or was cancelled). */
public final class JobNotDoneException extends RuntimeException {

    public JobNotDoneException(String id, JobState state) {
        super("render job " + id + " is " + state.json() + "; its image exists only once it is done");
    }
}

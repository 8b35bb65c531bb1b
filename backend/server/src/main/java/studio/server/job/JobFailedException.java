package studio.server.job;

/** A render that cannot finish, for a reason its message gives in the user's words (the job's error). */
public class JobFailedException extends RuntimeException {

    public JobFailedException(String message) {
        super(message);
    }
}

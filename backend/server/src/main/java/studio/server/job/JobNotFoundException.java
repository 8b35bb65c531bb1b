package studio.server.job;

/** No job has that id (it never existed, or it expired). */
public final class JobNotFoundException extends RuntimeException {

    public JobNotFoundException(String id) {
        super("no render job '" + id.replaceAll("[^A-Za-z0-9-]", "") + "'; it never existed or has expired");
    }
}

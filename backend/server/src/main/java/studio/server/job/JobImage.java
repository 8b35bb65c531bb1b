package studio.server.job;

/** A finished job's image and status. */
public record JobImage(JobStatus status, byte[] bytes) {
}

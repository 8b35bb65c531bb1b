package studio.server.job;

/**
 * A job as the API shows it.
 *
 * @param progress      finished tiles / all tiles, 0..1
 * @param raysPerSecond when done, else null
 * @param error         why it failed or was cancelled, else null
 */
public record JobStatus(String id, JobState state, double progress, long elapsedMillis, Double raysPerSecond,
                        int width, int height, String fileName, String mediaType, String error)
        implements JobEvent {
}

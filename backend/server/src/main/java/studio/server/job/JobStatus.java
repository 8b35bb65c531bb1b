package studio.server.job;

import java.util.Map;

import com.fasterxml.jackson.annotation.JsonInclude;

/**
 * A job as the API shows it.
 *
 * @param progress      finished tiles / all tiles, 0..1
 * @param raysPerSecond when done, else null
 * @param error         why it failed or was cancelled, else null
 * @param workers       in a cluster, the tiles each member (host:port) rendered; null (left out) in a
 *                      cluster of one
 */
public record JobStatus(String id, JobState state, double progress, long elapsedMillis, Double raysPerSecond,
                        int width, int height, String fileName, String mediaType, String error,
                        @JsonInclude(JsonInclude.Include.NON_NULL) Map<String, Integer> workers)
        implements JobEvent {
}

package studio.server.job;

import java.time.Duration;

/**
 * How render jobs run and how long they are kept.
 *
 * @param concurrent    jobs rendering at once (each uses renderThreads workers)
 * @param queue         jobs waiting; one more gets 429 with Retry-After
 * @param keepFinished  how long a finished job and its image stay available
 * @param maxFinished   at most this many finished jobs are kept (oldest dropped first)
 * @param abandonAfter  a queued or running job nobody has asked about (status, events or image)
 *                      for this long, and with no open event stream, is cancelled
 * @param renderThreads worker threads per render, 0 for all cores
 */
public record JobSettings(int concurrent, int queue, Duration keepFinished, int maxFinished, Duration abandonAfter,
                          int renderThreads) {

    public static final JobSettings DEFAULTS =
            new JobSettings(1, 8, Duration.ofMinutes(15), 50, Duration.ofMinutes(2), 0);
}

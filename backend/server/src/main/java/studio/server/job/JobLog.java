package studio.server.job;

import java.util.Locale;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import studio.server.scene.compiling.CompiledScene;

/**
 * A job's life in the log, one line at each step, under the logger {@code studio.jobs}: accepted
 * (what it renders), started (how long it waited), and ended (done, failed or cancelled, with its
 * figures). With {@code logging.structured.format.console} set, each is one JSON object.
 */
final class JobLog {

    private static final Logger log = LoggerFactory.getLogger("studio.jobs");

    private JobLog() {
    }

    static void accepted(String id, CompiledScene scene, boolean resumed, int waiting) {
        if (log.isInfoEnabled()) {
            log.info("job {} {}: {}x{} {}, {} samples per pixel, {} objects, {} lights; {} job(s) waiting", id,
                    resumed ? "taken over" : "accepted", scene.settings().width(), scene.settings().height(),
                    scene.format(), scene.settings().sampler().samplesPerPixel(), scene.scene().objectCount(),
                    scene.scene().lights().size(), waiting);
        }
    }

    static void started(String id, long waitedMillis) {
        log.info("job {} started after {} ms in the queue", id, waitedMillis);
    }

    /** The end of a job that was accepted: its state, time, speed, image size, and why it stopped. */
    static void ended(JobStatus end, int imageBytes) {
        if (!log.isInfoEnabled()) {
            return;
        }
        StringBuilder line = new StringBuilder("job ").append(end.id()).append(' ')
                .append(end.state().name().toLowerCase(Locale.ROOT)).append(" after ").append(end.elapsedMillis())
                .append(" ms");
        if (end.raysPerSecond() != null) {
            line.append(String.format(Locale.ROOT, ", %.1f M rays/s", end.raysPerSecond() / 1e6));
        }
        if (imageBytes > 0) {
            line.append(", ").append(imageBytes).append(" bytes of ").append(end.mediaType());
        }
        if (end.workers() != null && !end.workers().isEmpty()) {
            line.append(", tiles by member ").append(end.workers());
        }
        if (end.error() != null && !end.error().equals(end.state().name().toLowerCase(Locale.ROOT))) {
            line.append(": ").append(end.error()); // why, unless it only says the state again
        }
        log.info(line.toString());
    }
}

package studio.server.cluster;

import java.util.Set;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

import studio.server.job.JobListener;
import studio.server.job.JobState;
import studio.server.job.JobStatus;
import studio.server.job.TileEvent;

/**
 * Tells the cluster about a job this member runs: it is the job's own subscriber (on the job
 * service's sender threads, off the job's lock and the render threads), and writes each status to
 * the job table ({@link StatusUpdate}: never over the job's end), each event to the job's ring
 * buffer (its event log, which any member's event streams read), and last the end event. The end
 * of a job that ran, and a done job's image, are in the cluster's maps before the job itself reports
 * its end ({@link ClusterJobs#ending}); this writes them again only if that failed. A job taken over
 * from a member that died skips the tile events its first member published already.
 */
final class JobPublisher implements JobListener {

    private final String id;
    private final String owner;
    private final SealedMap<String, JobRecord> jobs;
    private final SealedMap<String, byte[]> images;
    private final EventLog events;
    private final Supplier<JobStatus> current;
    private final Supplier<byte[]> image;
    /** {@code x,y} of tiles whose events are in the ring buffer already (a job taken over). */
    private final Set<String> published;
    /** True once the job is handed over to another member: nothing more is written of it from here. */
    private final BooleanSupplier stopped;
    /** When the job table last had this job's progress (System.nanoTime). */
    private long progressWritten;
    /** Progress is written to the job table at most this often: a status read through another member lags by as much. */
    static final long PROGRESS_MILLIS = 250;

    JobPublisher(String id, String owner, SealedMap<String, JobRecord> jobs, SealedMap<String, byte[]> images,
                 EventLog events, Supplier<JobStatus> current, Supplier<byte[]> image, Set<String> published,
                 BooleanSupplier stopped) {
        this.stopped = stopped;
        this.id = id;
        this.owner = owner;
        this.jobs = jobs;
        this.images = images;
        this.events = events;
        this.current = current;
        this.image = image;
        this.published = published;
    }

    static String key(TileEvent tile) {
        return tile.x() + "," + tile.y();
    }

    @Override
    public void status(JobStatus status) {
        if (stopped.getAsBoolean()) {
            return;
        }
        jobs.update(id, new StatusUpdate(owner, status));
        events.add(status);
    }

    @Override
    public void tile(TileEvent tile) {
        if (stopped.getAsBoolean() || published.remove(key(tile))) {
            return;
        }
        events.add(tile);
        long now = System.nanoTime();
        if (now - progressWritten > PROGRESS_MILLIS * 1_000_000) {
            progressWritten = now;
            // the progress, for status through any member
            jobs.update(id, new StatusUpdate(owner, current.get()));
        }
    }

    @Override
    public void end(JobStatus status) {
        if (stopped.getAsBoolean()) {
            return;
        }
        if (status.state() == JobState.DONE && !images.containsKey(id)) {
            images.set(id, image.get());
        }
        jobs.update(id, new StatusUpdate(owner, status));
        events.add(status);
    }
}

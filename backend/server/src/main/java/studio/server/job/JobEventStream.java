package studio.server.job;

import java.io.IOException;

import org.springframework.http.MediaType;
import org.springframework.web.servlet.mvc.method.annotation.SseEmitter;

/**
 * One client's server-sent event stream of a job: {@code status}, {@code tile} and finally
 * {@code end}, then the stream closes. Its writes happen on its own sender thread (see
 * {@link JobSubscription}), so a client that does not read blocks nobody else. When the client goes
 * away (the container reports an async error, or the next write fails) the stream is dropped, and
 * the job is cancelled if nobody else watches it (see {@link JobService#disconnected}); when it
 * stops reading, the stream is closed and the job goes on.
 */
final class JobEventStream implements JobListener {

    /** An open stream lives at most this long; the client may reconnect. */
    static final long TIMEOUT_MILLIS = 60 * 60 * 1000L;

    private final String jobId;
    private final JobService service;
    private final SseEmitter emitter = new SseEmitter(TIMEOUT_MILLIS);

    JobEventStream(String jobId, JobService service) {
        this.jobId = jobId;
        this.service = service;
        // off the container's thread: see JobService#offContainerThread
        emitter.onCompletion(() -> service.offContainerThread(this::close));
        emitter.onTimeout(() -> service.offContainerThread(this::close));
        emitter.onError(e -> service.offContainerThread(this::disconnected));
    }

    SseEmitter emitter() {
        return emitter;
    }

    @Override
    public void status(JobStatus status) {
        send(SseEmitter.event().name("status").data(status, MediaType.APPLICATION_JSON));
    }

    @Override
    public void tile(TileEvent tile) {
        send(SseEmitter.event().name("tile").data(tile, MediaType.APPLICATION_JSON));
    }

    @Override
    public void end(JobStatus status) {
        if (send(SseEmitter.event().name("end").data(status, MediaType.APPLICATION_JSON))) {
            emitter.complete();
        }
    }

    /** Fell behind (the client does not read): the stream closes, the job goes on. */
    @Override
    public void dropped() {
        emitter.complete();
    }

    @Override
    public void heartbeat() {
        send(SseEmitter.event().comment("keep-alive"));
    }

    private boolean send(SseEmitter.SseEventBuilder event) {
        try {
            emitter.send(event);
            return true;
        } catch (IOException | IllegalStateException e) {
            disconnected();
            emitter.completeWithError(e);
            return false;
        }
    }

    private void disconnected() {
        service.disconnected(jobId, this);
    }

    private void close() {
        service.unsubscribe(jobId, this);
    }
}

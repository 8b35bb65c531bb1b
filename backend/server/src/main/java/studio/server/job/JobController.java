package studio.server.job;

import java.net.URI;

import org.springframework.http.MediaType;
import org.springframework.http.ResponseEntity;
import org.springframework.web.bind.annotation.DeleteMapping;
import org.springframework.web.bind.annotation.GetMapping;
import org.springframework.web.bind.annotation.PathVariable;
import org.springframework.web.bind.annotation.PostMapping;
import org.springframework.web.bind.annotation.RequestBody;
import org.springframework.web.bind.annotation.RestController;
import org.springframework.web.servlet.mvc.method.annotation.SseEmitter;

import jakarta.servlet.http.HttpServletRequest;

import studio.server.render.RenderedImage;
import studio.server.scene.format.SceneMediaTypes;
import studio.server.system.IntakeMemory;

/**
 * Render jobs: start, watch (status and an event stream of tiles), fetch the image, cancel. A job's
 * scene must be sent as JSON ({@link SceneMediaTypes}).
 */
@RestController
class JobController {

    private final JobService jobs;

    JobController(JobService jobs) {
        this.jobs = jobs;
    }

    /** The service reads the scene, as the render service does for POST /api/render. */
    @PostMapping(path = "/api/jobs", consumes = {SceneMediaTypes.JSON, SceneMediaTypes.JSON_SUFFIXED})
    ResponseEntity<JobStatus> start(@RequestBody(required = false) byte[] scene, HttpServletRequest request) {
        JobStatus status = jobs.start(scene != null ? scene : new byte[0], IntakeMemory.of(request));
        return ResponseEntity.accepted().location(URI.create("/api/jobs/" + status.id())).body(status);
    }

    @GetMapping("/api/jobs/{id}")
    JobStatus status(@PathVariable String id) {
        return jobs.status(id);
    }

    @GetMapping(path = "/api/jobs/{id}/events", produces = MediaType.TEXT_EVENT_STREAM_VALUE)
    SseEmitter events(@PathVariable String id) {
        JobEventStream stream = new JobEventStream(id, jobs);
        jobs.subscribe(id, stream);
        return stream.emitter();
    }

    @GetMapping("/api/jobs/{id}/image")
    ResponseEntity<byte[]> image(@PathVariable String id) {
        JobService.JobImage image = jobs.image(id);
        JobStatus status = image.status();
        return new RenderedImage(image.bytes(), status.mediaType(), status.fileName(), status.width(), status.height(),
                status.elapsedMillis(), status.raysPerSecond()).toResponse();
    }

    @DeleteMapping("/api/jobs/{id}")
    ResponseEntity<JobStatus> cancel(@PathVariable String id) {
        return ResponseEntity.accepted().body(jobs.cancel(id));
    }
}

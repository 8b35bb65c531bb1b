package studio.server.job;

import java.net.URI;
import java.security.Principal;

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
import studio.server.security.SignIn;
import studio.server.system.IntakeMemory;
import studio.server.system.StudioProperties;

/**
 * Render jobs: start, watch (status and an event stream of tiles), fetch the image, cancel. A job's
 * scene must be sent as JSON ({@link SceneMediaTypes}). A job belongs to the principal that started it
 * ("" with sign-in off): to anyone else, its id answers 404, as if it did not exist.
 */
@RestController
class JobController {

    private final JobService jobs;
    private final SignIn signIn;
    /** This member's running and queued places, which bound one principal's jobs by default. */
    private final int slots;

    JobController(JobService jobs, SignIn signIn, StudioProperties properties) {
        this.jobs = jobs;
        this.signIn = signIn;
        this.slots = properties.jobs().concurrent() + properties.jobs().queue();
    }

    /** The service reads the scene, as the render service does for POST /api/render. */
    @PostMapping(path = "/api/jobs", consumes = {SceneMediaTypes.JSON, SceneMediaTypes.JSON_SUFFIXED})
    ResponseEntity<JobStatus> start(@RequestBody(required = false) byte[] scene, HttpServletRequest request,
                                    Principal principal) {
        JobOwner owner = signIn.required() ? new JobOwner(SignIn.principal(principal), signIn.maxJobsPerPrincipal(slots))
                : JobOwner.ANYONE;
        JobStatus status = jobs.start(scene != null ? scene : new byte[0], IntakeMemory.of(request), owner);
        return ResponseEntity.accepted().location(URI.create("/api/jobs/" + status.id())).body(status);
    }

    @GetMapping("/api/jobs/{id}")
    JobStatus status(@PathVariable String id, Principal principal) {
        return jobs.status(id, SignIn.principal(principal));
    }

    @GetMapping(path = "/api/jobs/{id}/events", produces = MediaType.TEXT_EVENT_STREAM_VALUE)
    SseEmitter events(@PathVariable String id, Principal principal) {
        JobEventStream stream = new JobEventStream(id, jobs);
        jobs.subscribe(id, SignIn.principal(principal), stream);
        return stream.emitter();
    }

    @GetMapping("/api/jobs/{id}/image")
    ResponseEntity<byte[]> image(@PathVariable String id, Principal principal) {
        JobImage image = jobs.image(id, SignIn.principal(principal));
        JobStatus status = image.status();
        return new RenderedImage(image.bytes(), status.mediaType(), status.fileName(), status.width(), status.height(),
                status.elapsedMillis(), status.raysPerSecond()).toResponse();
    }

    @DeleteMapping("/api/jobs/{id}")
    ResponseEntity<JobStatus> cancel(@PathVariable String id, Principal principal) {
        return ResponseEntity.accepted().body(jobs.cancel(id, SignIn.principal(principal)));
    }
}

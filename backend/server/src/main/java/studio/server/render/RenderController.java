package studio.server.render;

import org.springframework.http.ContentDisposition;
import org.springframework.http.HttpHeaders;
import org.springframework.http.MediaType;
import org.springframework.http.ResponseEntity;
import org.springframework.web.bind.annotation.PostMapping;
import org.springframework.web.bind.annotation.RequestBody;
import org.springframework.web.bind.annotation.RestController;

/** POST /api/render: a scene in, the image out. */
@RestController
class RenderController {

    private final RenderService renderService;

    RenderController(RenderService renderService) {
        this.renderService = renderService;
    }

    @PostMapping("/api/render")
    ResponseEntity<byte[]> render(@RequestBody(required = false) byte[] scene) {
        RenderedImage image = renderService.render(scene != null ? scene : new byte[0]);
        return ResponseEntity.ok()
                .contentType(MediaType.parseMediaType(image.mediaType()))
                .header(HttpHeaders.CONTENT_DISPOSITION,
                        ContentDisposition.attachment().filename(image.fileName()).build().toString())
                .header("X-Render-Millis", Long.toString(image.elapsedMillis()))
                .header("X-Rays-Per-Second", Long.toString(Math.round(image.raysPerSecond())))
                .header("X-Image-Size", image.width() + "x" + image.height())
                .body(image.bytes());
    }
}

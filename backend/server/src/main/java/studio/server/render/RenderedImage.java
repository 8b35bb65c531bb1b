package studio.server.render;

import org.springframework.http.ContentDisposition;
import org.springframework.http.HttpHeaders;
import org.springframework.http.MediaType;
import org.springframework.http.ResponseEntity;

/** An encoded image with what the client needs to save it and the render's figures. */
public record RenderedImage(byte[] bytes, String mediaType, String fileName, int width, int height,
                            long elapsedMillis, double raysPerSecond) {

    /** The 200 response both APIs send: the image as an attachment, with the render's figures in headers. */
    public ResponseEntity<byte[]> toResponse() {
        return ResponseEntity.ok()
                .contentType(MediaType.parseMediaType(mediaType))
                .header(HttpHeaders.CONTENT_DISPOSITION, ContentDisposition.attachment().filename(fileName).build()
                        .toString())
                .header("X-Render-Millis", Long.toString(elapsedMillis))
                .header("X-Rays-Per-Second", Long.toString(Math.round(raysPerSecond)))
                .header("X-Image-Size", width + "x" + height)
                .body(bytes);
    }
}

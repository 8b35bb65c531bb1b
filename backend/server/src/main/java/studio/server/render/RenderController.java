package studio.server.render;

import java.util.concurrent.CompletionException;

import org.springframework.http.ResponseEntity;
import org.springframework.web.bind.annotation.PostMapping;
import org.springframework.web.bind.annotation.RequestBody;
import org.springframework.web.bind.annotation.RestController;
import org.springframework.web.context.request.async.DeferredResult;

import jakarta.servlet.http.HttpServletRequest;
import studio.server.system.IntakeMemory;

/**
 * POST /api/render: a scene in, the image out. The render runs on the render service's threads
 * while the request waits asynchronously; a client that disconnects cancels its render at the next
 * tile ({@link ClientProbe} notices it, or the container reports an async error).
 */
@RestController
class RenderController {

    private final RenderService renderService;

    RenderController(RenderService renderService) {
        this.renderService = renderService;
    }

    @PostMapping("/api/render")
    DeferredResult<ResponseEntity<byte[]>> render(@RequestBody(required = false) byte[] scene,
                                                  HttpServletRequest request) {
        ClientProbe client = ClientProbe.of(request);
        RenderService.Ticket ticket;
        try {
            ticket = renderService.start(scene != null ? scene : new byte[0], client, IntakeMemory.of(request));
        } catch (RuntimeException e) {
            client.close();
            throw e;
        }
        DeferredResult<ResponseEntity<byte[]>> response = new DeferredResult<>(renderService.responseTimeoutMillis());
        response.onError(error -> {
            client.close();
            ticket.cancel();
        });
        response.onTimeout(() -> {
            client.close();
            ticket.cancel();
        });
        response.onCompletion(client::close);
        ticket.result().whenComplete((image, error) -> {
            if (error == null) {
                response.setResult(image.toResponse());
            } else {
                response.setErrorResult(error instanceof CompletionException wrapped && wrapped.getCause() != null
                        ? wrapped.getCause() : error);
            }
        });
        return response;
    }
}

package studio.server.render;

import java.time.Duration;
import java.util.concurrent.CompletionException;

import org.springframework.http.ResponseEntity;
import org.springframework.web.bind.annotation.PostMapping;
import org.springframework.web.bind.annotation.RequestBody;
import org.springframework.web.bind.annotation.RestController;
import org.springframework.web.context.request.async.DeferredResult;

import jakarta.servlet.http.HttpServletRequest;

import studio.engine.render.RenderCancelledException;
import studio.server.scene.format.SceneMediaTypes;
import studio.server.system.IntakeMemory;

/**
 * POST /api/render: a scene in, the image out. The render runs on the render service's threads
 * while the request waits asynchronously; a client that disconnects cancels its render within a few
 * milliseconds ({@link ClientProbe} notices it, or the container reports an async error). Every
 * answer but the image is a problem: 422 when the render ran out of its time budget, 503 with
 * Retry-After when the server is busy, stopping (and cancelled the render), or gave up waiting for
 * the render (its time budget and a minute to encode the image,
 * {@link RenderService#responseTimeoutMillis}). The body must be sent as JSON ({@link SceneMediaTypes}).
 */
@RestController
class RenderController {

    private final RenderService renderService;

    RenderController(RenderService renderService) {
        this.renderService = renderService;
    }

    @PostMapping(path = "/api/render", consumes = {SceneMediaTypes.JSON, SceneMediaTypes.JSON_SUFFIXED})
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
        long timeoutMillis = renderService.responseTimeoutMillis();
        DeferredResult<ResponseEntity<byte[]>> response = new DeferredResult<>(timeoutMillis);
        response.onError(error -> {
            client.close();
            ticket.cancel();
        });
        response.onTimeout(() -> {
            client.close();
            ticket.cancel();
            // else Spring answers its AsyncRequestTimeoutException: a 503 without detail or Retry-After
            response.setErrorResult(new RenderBusyException("the server could not finish the render within "
                    + RenderBudget.describe(Duration.ofMillis(timeoutMillis)) + "; try again shortly"));
        });
        response.onCompletion(client::close);
        ticket.result().whenComplete((image, error) -> {
            if (error == null) {
                response.setResult(image.toResponse());
            } else {
                response.setErrorResult(answer(error instanceof CompletionException wrapped
                        && wrapped.getCause() != null ? wrapped.getCause() : error));
            }
        });
        return response;
    }

    /**
     * A render's failure as its answer: a cancelled render is a 503 with Retry-After (only a client
     * that is still there sees it: its render was stopped because the server is stopping); any other
     * failure carries its own answer ({@link RenderTimeExceededException}) or is unexpected.
     */
    private static Throwable answer(Throwable failure) {
        return failure instanceof RenderCancelledException ? new RenderBusyException("the render was cancelled "
                + "before it finished (the server is shutting down); try again shortly") : failure;
    }
}

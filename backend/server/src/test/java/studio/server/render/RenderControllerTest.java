package studio.server.render;

import static org.hamcrest.Matchers.containsString;
import static org.hamcrest.Matchers.not;
import static org.mockito.ArgumentMatchers.any;
import static org.mockito.ArgumentMatchers.eq;
import static org.mockito.BDDMockito.given;
import static org.mockito.Mockito.mock;
import static org.mockito.Mockito.never;
import static org.mockito.Mockito.verify;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.asyncDispatch;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.get;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.post;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.content;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.header;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.jsonPath;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.status;

import java.time.Duration;
import java.util.concurrent.CompletableFuture;

import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.webmvc.test.autoconfigure.WebMvcTest;
import org.springframework.http.HttpHeaders;
import org.springframework.http.MediaType;
import org.springframework.test.context.bean.override.mockito.MockitoBean;
import org.springframework.mock.web.MockAsyncContext;
import org.springframework.test.web.servlet.MockMvc;
import org.springframework.test.web.servlet.MvcResult;

import studio.engine.render.RenderCancelledException;
import studio.server.AsyncMvc;

/** The render endpoint's mapping of service outcomes onto HTTP, with the service mocked. */
@WebMvcTest(RenderController.class)
class RenderControllerTest {

    @Autowired
    MockMvc mvc;

    @MockitoBean
    RenderService renderService;

    @Test
    void busyServerGives503WithRetryAfter() throws Exception {
        given(renderService.start(any(), any(), any())).willThrow(new RenderBusyException());
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content("{\"objects\":[]}"))
                .andExpect(status().isServiceUnavailable())
                .andExpect(header().string(HttpHeaders.RETRY_AFTER, "5"))
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(503))
                .andExpect(jsonPath("$.detail").value(containsString("busy")));
    }

    @Test
    void unexpectedFailureGives500ProblemWithoutInternals() throws Exception {
        given(renderService.start(any(), any(), any())).willThrow(new IllegalStateException("secret internal state"));
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content("{\"objects\":[]}"))
                .andExpect(status().isInternalServerError())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(500))
                .andExpect(jsonPath("$.detail").value(not(containsString("secret"))));
    }

    @Test
    void passesTheBodyAndMapsTheImage() throws Exception {
        byte[] body = "{\"objects\":[]}".getBytes();
        RenderService.Ticket ticket = ticket(CompletableFuture.completedFuture(
                new RenderedImage(new byte[] {1, 2, 3}, "image/jpeg", "scene.jpg", 3, 2, 42, 1234.4)));
        given(renderService.start(eq(body), any(), any())).willReturn(ticket);
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content(body))
                .andExpect(status().isOk())
                .andExpect(content().contentType(MediaType.IMAGE_JPEG))
                .andExpect(content().bytes(new byte[] {1, 2, 3}))
                .andExpect(header().string(HttpHeaders.CONTENT_DISPOSITION, "attachment; filename=\"scene.jpg\""))
                .andExpect(header().string("X-Render-Millis", "42"))
                .andExpect(header().string("X-Rays-Per-Second", "1234"))
                .andExpect(header().string("X-Image-Size", "3x2"));
    }

    @Test
    void getOnRenderGives405Problem() throws Exception {
        mvc.perform(get("/api/render"))
                .andExpect(status().isMethodNotAllowed())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(405));
        verify(renderService, never()).start(any(), any(), any());
    }

    @Test
    void unknownPathIsNotRendered() throws Exception {
        mvc.perform(post("/api/renders").content("{\"objects\":[]}"))
                .andExpect(status().isNotFound())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON));
        verify(renderService, never()).start(any(), any(), any());
    }

    @Test
    void renderOverItsTimeBudgetGives422SayingSo() throws Exception {
        RenderService.Ticket ticket = ticket(
                CompletableFuture.failedFuture(new RenderTimeExceededException(Duration.ofMinutes(5))));
        given(renderService.start(any(), any(), any())).willReturn(ticket);
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content("{\"objects\":[]}"))
                .andExpect(status().isUnprocessableContent())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.title").value("Render time budget exceeded"))
                .andExpect(jsonPath("$.detail").value(containsString("5 min")))
                .andExpect(jsonPath("$.detail").value(containsString("studio.limits.max-render-time")));
    }

    /** Only a client still there sees it: its render was stopped because the server is stopping. */
    @Test
    void renderCancelledByShutdownGives503WithRetryAfter() throws Exception {
        RenderService.Ticket ticket = ticket(CompletableFuture.failedFuture(new RenderCancelledException()));
        given(renderService.start(any(), any(), any())).willReturn(ticket);
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content("{\"objects\":[]}"))
                .andExpect(status().isServiceUnavailable())
                .andExpect(header().string(HttpHeaders.RETRY_AFTER, "5"))
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.title").value("Service Unavailable"))
                .andExpect(jsonPath("$.detail").value("the render was cancelled before it finished (the server is "
                        + "shutting down); try again shortly"))
                .andExpect(jsonPath("$.instance").value("/api/render"));
    }

    @Test
    void clientThatGoesAwayCancelsItsRender() throws Exception {
        CompletableFuture<RenderedImage> never = new CompletableFuture<>();
        RenderService.Ticket ticket = ticket(never);
        given(renderService.start(any(), any(), any())).willReturn(ticket);
        MvcResult result = mvc.perform(post("/api/render").contentType(MediaType.APPLICATION_JSON)
                .content("{\"objects\":[]}")).andReturn();
        // what the container does when the connection drops during an async request
        var listeners = ((MockAsyncContext) result.getRequest().getAsyncContext()).getListeners();
        for (var listener : listeners) {
            listener.onError(new jakarta.servlet.AsyncEvent(result.getRequest().getAsyncContext(),
                    new java.io.IOException("connection reset")));
        }
        verify(ticket).cancel();
    }

    /**
     * The request's own timeout (the time budget and a minute) passes before the render ends: the
     * answer is a problem saying so, with Retry-After, not Spring's bare timeout 503.
     */
    @Test
    void renderTheServerGivesUpWaitingForGives503WithRetryAfterAndCancelsIt() throws Exception {
        CompletableFuture<RenderedImage> never = new CompletableFuture<>();
        RenderService.Ticket ticket = ticket(never);
        given(renderService.start(any(), any(), any())).willReturn(ticket);
        given(renderService.responseTimeoutMillis()).willReturn(62_000L);
        MvcResult result = mvc.perform(post("/api/render").contentType(MediaType.APPLICATION_JSON)
                .content("{\"objects\":[]}")).andReturn();
        // what the container does when the async request's timeout passes
        var context = (MockAsyncContext) result.getRequest().getAsyncContext();
        for (var listener : context.getListeners()) {
            listener.onTimeout(new jakarta.servlet.AsyncEvent(context));
        }
        mvc.perform(asyncDispatch(result))
                .andExpect(status().isServiceUnavailable())
                .andExpect(header().string(HttpHeaders.RETRY_AFTER, "5"))
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(503))
                .andExpect(jsonPath("$.detail").value(containsString("62 s")));
        verify(ticket).cancel();
    }

    private static RenderService.Ticket ticket(CompletableFuture<RenderedImage> result) {
        RenderService.Ticket ticket = mock(RenderService.Ticket.class);
        given(ticket.result()).willReturn(result);
        return ticket;
    }
}

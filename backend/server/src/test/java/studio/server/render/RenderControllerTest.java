package studio.server.render;

import static org.hamcrest.Matchers.containsString;
import static org.hamcrest.Matchers.not;
import static org.mockito.ArgumentMatchers.any;
import static org.mockito.BDDMockito.given;
import static org.mockito.Mockito.never;
import static org.mockito.Mockito.verify;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.post;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.content;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.header;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.jsonPath;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.status;

import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.webmvc.test.autoconfigure.WebMvcTest;
import org.springframework.http.HttpHeaders;
import org.springframework.http.MediaType;
import org.springframework.test.context.bean.override.mockito.MockitoBean;
import org.springframework.test.web.servlet.MockMvc;

/** The render endpoint's mapping of service outcomes onto HTTP, with the service mocked. */
@WebMvcTest(RenderController.class)
class RenderControllerTest {

    @Autowired
    MockMvc mvc;

    @MockitoBean
    RenderService renderService;

    @Test
    void busyServerGives503WithRetryAfter() throws Exception {
        given(renderService.render(any())).willThrow(new RenderBusyException());
        mvc.perform(post("/api/render").contentType(MediaType.APPLICATION_JSON).content("{\"objects\":[]}"))
                .andExpect(status().isServiceUnavailable())
                .andExpect(header().string(HttpHeaders.RETRY_AFTER, "5"))
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(503))
                .andExpect(jsonPath("$.detail").value(containsString("busy")));
    }

    @Test
    void unexpectedFailureGives500ProblemWithoutInternals() throws Exception {
        given(renderService.render(any())).willThrow(new IllegalStateException("secret internal state"));
        mvc.perform(post("/api/render").contentType(MediaType.APPLICATION_JSON).content("{\"objects\":[]}"))
                .andExpect(status().isInternalServerError())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(500))
                .andExpect(jsonPath("$.detail").value(not(containsString("secret"))));
    }

    @Test
    void passesTheBodyAndMapsTheImage() throws Exception {
        byte[] body = "{\"objects\":[]}".getBytes();
        given(renderService.render(body)).willReturn(
                new RenderedImage(new byte[] {1, 2, 3}, "image/jpeg", "scene.jpg", 3, 2, 42, 1234.4));
        mvc.perform(post("/api/render").contentType(MediaType.APPLICATION_JSON).content(body))
                .andExpect(status().isOk())
                .andExpect(content().contentType(MediaType.IMAGE_JPEG))
                .andExpect(content().bytes(new byte[] {1, 2, 3}))
                .andExpect(header().string(HttpHeaders.CONTENT_DISPOSITION, "attachment; filename=\"scene.jpg\""))
                .andExpect(header().string("X-Render-Millis", "42"))
                .andExpect(header().string("X-Rays-Per-Second", "1234"))
                .andExpect(header().string("X-Image-Size", "3x2"));
    }

    @Test
    void unknownPathIsNotRendered() throws Exception {
        mvc.perform(post("/api/renders").content("{\"objects\":[]}"))
                .andExpect(status().isNotFound())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON));
        verify(renderService, never()).render(any());
    }
}

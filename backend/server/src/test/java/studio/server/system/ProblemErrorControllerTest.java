package studio.server.system;

import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.get;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.post;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.content;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.jsonPath;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.status;

import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.webmvc.test.autoconfigure.WebMvcTest;
import org.springframework.http.MediaType;
import org.springframework.test.web.servlet.MockMvc;

import jakarta.servlet.RequestDispatcher;

/**
 * The container's error dispatch to /error as a controller slice: the status it hands over becomes
 * an RFC 9457 problem with a detail in the user's words and the failed path, cleaned, as its instance.
 * What the real container dispatches there is ErrorResponsesTest's and ContainerErrorsTest's.
 */
@WebMvcTest(ProblemErrorController.class)
class ProblemErrorControllerTest {

    @Autowired
    MockMvc mvc;

    @Test
    void errorDispatchAnswersItsStatusAsAProblemNamingThePath() throws Exception {
        mvc.perform(get("/error").requestAttr(RequestDispatcher.ERROR_STATUS_CODE, 405)
                        .requestAttr(RequestDispatcher.ERROR_REQUEST_URI, "/api/render"))
                .andExpect(status().isMethodNotAllowed())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(405))
                .andExpect(jsonPath("$.title").value("Method Not Allowed"))
                .andExpect(jsonPath("$.detail").value("this method is not allowed here"))
                .andExpect(jsonPath("$.instance").value("/api/render"));
    }

    @Test
    void errorDispatchOfAnyMethodIsAProblem() throws Exception {
        mvc.perform(post("/error").requestAttr(RequestDispatcher.ERROR_STATUS_CODE, 413))
                .andExpect(status().isContentTooLarge())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.detail").value("the request is too large"))
                // without the failed path, Spring names the path that answered
                .andExpect(jsonPath("$.instance").value("/error"));
    }

    @Test
    void pathInTheInstanceKeepsOnlyPlainCharacters() throws Exception {
        mvc.perform(get("/error").requestAttr(RequestDispatcher.ERROR_STATUS_CODE, 400)
                        .requestAttr(RequestDispatcher.ERROR_REQUEST_URI, "/api/<script>\"x\" y"))
                .andExpect(status().isBadRequest())
                .andExpect(jsonPath("$.instance").value("/api/scriptxy"));
    }

    @Test
    void statusThatIsNoHttpStatusGives500() throws Exception {
        mvc.perform(get("/error").requestAttr(RequestDispatcher.ERROR_STATUS_CODE, 299))
                .andExpect(status().isInternalServerError())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(500));
    }

    @Test
    void errorPathAskedForDirectlyIsNotFound() throws Exception {
        mvc.perform(get("/error"))
                .andExpect(status().isNotFound())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(404))
                .andExpect(jsonPath("$.detail").value("there is nothing at this path"));
    }
}

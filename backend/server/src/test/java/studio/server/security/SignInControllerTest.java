package studio.server.security;

import static org.hamcrest.Matchers.containsString;
import static org.mockito.ArgumentMatchers.any;
import static org.mockito.BDDMockito.given;
import static org.mockito.Mockito.never;
import static org.mockito.Mockito.verify;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.get;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.post;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.content;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.header;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.jsonPath;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.status;

import java.time.Duration;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.webmvc.test.autoconfigure.WebMvcTest;
import org.springframework.http.HttpHeaders;
import org.springframework.http.MediaType;
import org.springframework.test.context.bean.override.mockito.MockitoBean;
import org.springframework.test.web.servlet.MockMvc;

/**
 * GET /api/me and POST /api/preview/tickets as a controller slice, with sign-in and the tickets
 * mocked and the principal given by the request. Who may call them (401 and WWW-Authenticate
 * without a key) is the security chain's, tested end to end in SignInApiTest.
 */
@WebMvcTest(SignInController.class)
class SignInControllerTest {

    @Autowired
    MockMvc mvc;

    @MockitoBean
    SignIn signIn;

    @MockitoBean
    PreviewTickets tickets;

    @BeforeEach
    void lifetime() {
        given(tickets.lifetime()).willReturn(Duration.ofSeconds(30));
    }

    @Test
    void meWithoutAPrincipalIsNobodyWhoNeedNotSignIn() throws Exception {
        mvc.perform(get("/api/me"))
                .andExpect(status().isOk())
                .andExpect(content().contentTypeCompatibleWith(MediaType.APPLICATION_JSON))
                .andExpect(jsonPath("$.principal").value(""))
                .andExpect(jsonPath("$.signInRequired").value(false));
    }

    @Test
    void meNamesTheSignedInPrincipalAndThatSignInIsRequired() throws Exception {
        given(signIn.required()).willReturn(true);
        mvc.perform(get("/api/me").principal(() -> "bob"))
                .andExpect(status().isOk())
                .andExpect(jsonPath("$.principal").value("bob"))
                .andExpect(jsonPath("$.signInRequired").value(true));
    }

    @Test
    void ticketIsIssuedToThePrincipalWithItsLifetime() throws Exception {
        given(tickets.issue("alice")).willReturn("t-123");
        mvc.perform(post("/api/preview/tickets").principal(() -> "alice"))
                .andExpect(status().isOk())
                .andExpect(content().contentTypeCompatibleWith(MediaType.APPLICATION_JSON))
                .andExpect(jsonPath("$.ticket").value("t-123"))
                .andExpect(jsonPath("$.expiresInSeconds").value(30));
    }

    @Test
    void ticketWithSignInOffIsIssuedToNobody() throws Exception {
        given(tickets.issue("")).willReturn("t-0");
        mvc.perform(post("/api/preview/tickets"))
                .andExpect(status().isOk())
                .andExpect(jsonPath("$.ticket").value("t-0"));
    }

    @Test
    void tooManyUnusedTicketsGive429WithRetryAfterNamingTheLimit() throws Exception {
        mvc.perform(post("/api/preview/tickets").principal(() -> "alice"))
                .andExpect(status().isTooManyRequests())
                .andExpect(header().string(HttpHeaders.RETRY_AFTER, "30"))
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(429))
                .andExpect(jsonPath("$.detail").value(containsString("studio.security.max-tickets-per-principal")))
                .andExpect(jsonPath("$.detail").value(containsString("30 s")));
    }

    @Test
    void getOnTicketsGives405ProblemAndIssuesNone() throws Exception {
        mvc.perform(get("/api/preview/tickets"))
                .andExpect(status().isMethodNotAllowed())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(405));
        verify(tickets, never()).issue(any());
    }

    @Test
    void unknownPathGives404Problem() throws Exception {
        mvc.perform(get("/api/you"))
                .andExpect(status().isNotFound())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(404));
    }
}

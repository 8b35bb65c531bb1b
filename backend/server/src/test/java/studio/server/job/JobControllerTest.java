package studio.server.job;

import static org.hamcrest.Matchers.containsString;
import static org.mockito.ArgumentMatchers.any;
import static org.mockito.ArgumentMatchers.anyInt;
import static org.mockito.ArgumentMatchers.eq;
import static org.mockito.BDDMockito.given;
import static org.mockito.Mockito.never;
import static org.mockito.Mockito.verify;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.delete;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.get;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.post;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.content;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.header;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.jsonPath;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.status;

import org.junit.jupiter.api.Test;
import org.mockito.ArgumentCaptor;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.context.properties.EnableConfigurationProperties;
import org.springframework.boot.test.context.TestConfiguration;
import org.springframework.boot.webmvc.test.autoconfigure.WebMvcTest;
import org.springframework.http.HttpHeaders;
import org.springframework.http.MediaType;
import org.springframework.test.context.bean.override.mockito.MockitoBean;
import org.springframework.test.web.servlet.MockMvc;

import studio.server.security.SignIn;
import studio.server.system.StudioProperties;

/** The jobs endpoints' mapping of the job service's outcomes onto HTTP, with the service mocked. */
@WebMvcTest(JobController.class)
class JobControllerTest {

    private static final String SCENE = "{\"objects\":[]}";

    @Autowired
    MockMvc mvc;

    @MockitoBean
    JobService jobs;

    @MockitoBean
    SignIn signIn;

    /** The limits' defaults, as the service reads them. */
    @TestConfiguration
    @EnableConfigurationProperties(StudioProperties.class)
    static class Properties {
    }

    private static JobStatus job(String id, JobState state) {
        return new JobStatus(id, state, 0, 0, null, 32, 24, "scene.png", "image/png", null, null);
    }

    @Test
    void startAnswers202WithTheJobsLocation() throws Exception {
        given(jobs.start(any(), any(), any())).willReturn(job("abc", JobState.QUEUED));
        mvc.perform(post("/api/jobs").contentType(MediaType.APPLICATION_JSON).content(SCENE))
                .andExpect(status().isAccepted())
                .andExpect(header().string(HttpHeaders.LOCATION, "/api/jobs/abc"))
                .andExpect(jsonPath("$.id").value("abc"))
                .andExpect(jsonPath("$.state").value("queued"))
                .andExpect(jsonPath("$.workers").doesNotExist());
    }

    @Test
    void withSignInOffAJobBelongsToAnyone() throws Exception {
        given(jobs.start(any(), any(), any())).willReturn(job("abc", JobState.QUEUED));
        mvc.perform(post("/api/jobs").contentType(MediaType.APPLICATION_JSON).content(SCENE))
                .andExpect(status().isAccepted());
        verify(jobs).start(eq(SCENE.getBytes()), any(), eq(JobOwner.ANYONE));
    }

    @Test
    void withSignInOnAJobBelongsToThePrincipalWithinTheirLimit() throws Exception {
        given(signIn.required()).willReturn(true);
        given(signIn.maxJobsPerPrincipal(anyInt())).willReturn(3);
        given(jobs.start(any(), any(), any())).willReturn(job("abc", JobState.QUEUED));
        mvc.perform(post("/api/jobs").contentType(MediaType.APPLICATION_JSON).content(SCENE)
                        .principal(() -> "alice"))
                .andExpect(status().isAccepted());
        ArgumentCaptor<JobOwner> owner = ArgumentCaptor.forClass(JobOwner.class);
        verify(jobs).start(any(), any(), owner.capture());
        org.assertj.core.api.Assertions.assertThat(owner.getValue()).isEqualTo(new JobOwner("alice", 3));
    }

    @Test
    void aFullQueueGives429WithRetryAfter() throws Exception {
        given(jobs.start(any(), any(), any())).willThrow(new JobQueueFullException(7));
        mvc.perform(post("/api/jobs").contentType(MediaType.APPLICATION_JSON).content(SCENE))
                .andExpect(status().isTooManyRequests())
                .andExpect(header().string(HttpHeaders.RETRY_AFTER, "7"))
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(429));
    }

    @Test
    void aSceneThatIsNotJsonGives415AndNoJob() throws Exception {
        mvc.perform(post("/api/jobs").contentType(MediaType.TEXT_PLAIN).content(SCENE))
                .andExpect(status().isUnsupportedMediaType())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON));
        verify(jobs, never()).start(any(), any(), any());
    }

    @Test
    void anUnknownJobGives404Problem() throws Exception {
        given(jobs.status("nope", "")).willThrow(new JobNotFoundException("nope"));
        mvc.perform(get("/api/jobs/nope"))
                .andExpect(status().isNotFound())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(404))
                .andExpect(jsonPath("$.detail").value(containsString("nope")));
    }

    @Test
    void statusIsAskedForTheSignedInPrincipal() throws Exception {
        given(jobs.status("abc", "alice")).willReturn(job("abc", JobState.RUNNING));
        mvc.perform(get("/api/jobs/abc").principal(() -> "alice"))
                .andExpect(status().isOk())
                .andExpect(jsonPath("$.state").value("running"));
    }

    @Test
    void theImageOfAnUnfinishedJobGives409() throws Exception {
        given(jobs.image("abc", "")).willThrow(new JobNotDoneException("abc", JobState.RUNNING));
        mvc.perform(get("/api/jobs/abc/image"))
                .andExpect(status().isConflict())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(409));
    }

    @Test
    void aFinishedJobsImageComesUnderItsFileName() throws Exception {
        JobStatus done = new JobStatus("abc", JobState.DONE, 1, 42, 1000.0, 32, 24, "scene.png", "image/png", null,
                null);
        given(jobs.image("abc", "")).willReturn(new JobImage(done, new byte[] {1, 2, 3}));
        mvc.perform(get("/api/jobs/abc/image"))
                .andExpect(status().isOk())
                .andExpect(content().contentType(MediaType.IMAGE_PNG))
                .andExpect(content().bytes(new byte[] {1, 2, 3}))
                .andExpect(header().string(HttpHeaders.CONTENT_DISPOSITION, "attachment; filename=\"scene.png\""));
    }

    @Test
    void cancelAnswers202WithTheStatus() throws Exception {
        given(jobs.cancel("abc", "")).willReturn(job("abc", JobState.CANCELLED));
        mvc.perform(delete("/api/jobs/abc"))
                .andExpect(status().isAccepted())
                .andExpect(jsonPath("$.state").value("cancelled"));
    }
}

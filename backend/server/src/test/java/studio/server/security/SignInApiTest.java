package studio.server.security;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.net.http.WebSocket;
import java.net.http.WebSocketHandshakeException;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;

import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * Sign-in on, over a real socket: API keys and JWTs at once, jobs that only their principal sees, the
 * live view's tickets, the per-principal limits, and what the actuator shows to whom.
 */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT, properties = {
        "studio.security.api-keys=alice:alice-key-3f9a,bob:bob-key-77c1,carol:carol-key-0b2e",
        "spring.security.oauth2.resourceserver.jwt.public-key-location=classpath:security/jwt-test-public.pem",
        "studio.security.max-jobs-per-principal=1", "studio.security.max-live-views-per-principal=1",
        "studio.jobs.concurrent=1", "studio.jobs.queue=4", "studio.render-threads=1"})
class SignInApiTest {

    static final String ALICE = "alice-key-3f9a", BOB = "bob-key-77c1", CAROL = "carol-key-0b2e";
    private static final JsonMapper JSON = JsonMapper.builder().build();
    private static final HttpClient HTTP = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
    /** Big enough to still be running when the test acts on it. */
    private static final String LARGE = """
            {"name": "sign-in-test", "image": {"width": 1024, "height": 768}, "render": {"samples": 256},
             "objects": [{"type": "sphere", "material": {"type": "glass"}}, {"type": "plane"}]}""";

    @LocalServerPort
    int port;

    /** Jobs to cancel after each test, with their owner's key. */
    private final List<String[]> started = new ArrayList<>();
    private final List<WebSocket> sockets = new ArrayList<>();

    @AfterEach
    void cleanUp() throws Exception {
        for (String[] job : started) {
            send(HttpRequest.newBuilder(uri("/api/jobs/" + job[0])).DELETE(), job[1]);
        }
        for (WebSocket socket : sockets) {
            socket.abort();
        }
    }

    private URI uri(String path) {
        return URI.create("http://localhost:" + port + path);
    }

    private HttpResponse<String> send(HttpRequest.Builder request, String bearer) throws Exception {
        if (bearer != null) {
            request.header("Authorization", "Bearer " + bearer);
        }
        return HTTP.send(request.build(), HttpResponse.BodyHandlers.ofString());
    }

    private HttpResponse<String> get(String path, String bearer) throws Exception {
        return send(HttpRequest.newBuilder(uri(path)), bearer);
    }

    private HttpResponse<String> startJob(String bearer) throws Exception {
        HttpResponse<String> response = send(HttpRequest.newBuilder(uri("/api/jobs"))
                .header("Content-Type", "application/json").POST(HttpRequest.BodyPublishers.ofString(LARGE)), bearer);
        if (response.statusCode() == 202) {
            started.add(new String[] {JSON.readTree(response.body()).get("id").asString(), bearer});
        }
        return response;
    }

    private WebSocket openLiveView(String query, Map<String, String> headers) throws Exception {
        WebSocket.Builder builder = HTTP.newWebSocketBuilder().connectTimeout(Duration.ofSeconds(5));
        headers.forEach(builder::header);
        WebSocket socket = builder.buildAsync(URI.create("ws://localhost:" + port + "/api/preview" + query),
                new WebSocket.Listener() {
                }).get(10, TimeUnit.SECONDS);
        sockets.add(socket);
        return socket;
    }

    /** The status a refused upgrade answered. */
    private HttpResponse<String> refusedLiveView(String query, Map<String, String> headers) {
        ExecutionException refused = assertThrows(ExecutionException.class, () -> openLiveView(query, headers));
        assertThat(refused.getCause()).isInstanceOf(WebSocketHandshakeException.class);
        @SuppressWarnings("unchecked")
        HttpResponse<String> response = (HttpResponse<String>) ((WebSocketHandshakeException) refused.getCause())
                .getResponse();
        return response;
    }

    private static void assertProblem(HttpResponse<String> response, int status) throws Exception {
        assertThat(response.statusCode()).isEqualTo(status);
        assertThat(response.headers().firstValue("Content-Type")).hasValueSatisfying(
                type -> assertThat(type).startsWith("application/problem+json"));
        assertThat(JSON.readTree(response.body()).get("status").asInt()).isEqualTo(status);
    }

    private static String wwwAuthenticate(HttpResponse<String> response) {
        return response.headers().firstValue("WWW-Authenticate").orElse("");
    }

    @Test
    void apiWithoutKeyIsRefusedWithAProblemThatAsksForABearerToken() throws Exception {
        HttpResponse<String> response = get("/api/scenes", null);
        assertProblem(response, 401);
        assertThat(wwwAuthenticate(response)).isEqualTo("Bearer");
    }

    @Test
    void apiWithAnUnknownKeyIsRefusedAsAnInvalidToken() throws Exception {
        HttpResponse<String> response = get("/api/scenes", "alice-key-3f9b");
        assertProblem(response, 401);
        assertThat(wwwAuthenticate(response)).startsWith("Bearer").contains("invalid_token");
        assertThat(response.body()).doesNotContain("alice-key-3f9b");
    }

    @Test
    void apiWithAKeyAnswersAndNamesTheKeysPrincipal() throws Exception {
        assertThat(get("/api/scenes", ALICE).statusCode()).isEqualTo(200);
        JsonNode me = JSON.readTree(get("/api/me", BOB).body());
        assertThat(me.get("principal").asString()).isEqualTo("bob");
        assertThat(me.get("signInRequired").asBoolean()).isTrue();
    }

    @Test
    void unknownPathIsRefusedBeforeSignInAndNotFoundAfter() throws Exception {
        assertProblem(get("/api/nope", null), 401);
        assertProblem(get("/api/nope", ALICE), 404);
        assertProblem(get("/nope.html", null), 401);
        assertProblem(get("/nope.html", ALICE), 404);
        assertProblem(get("/api;x=y/scenes", null), 401);
    }

    @Test
    void anotherPrincipalsJobDoesNotExistForThem() throws Exception {
        HttpResponse<String> started = startJob(ALICE);
        assertThat(started.statusCode()).isEqualTo(202);
        String id = JSON.readTree(started.body()).get("id").asString();

        assertProblem(get("/api/jobs/" + id, BOB), 404);
        assertProblem(send(HttpRequest.newBuilder(uri("/api/jobs/" + id + "/events"))
                .header("Accept", "text/event-stream, application/problem+json"), BOB), 404);
        assertProblem(get("/api/jobs/" + id + "/image", BOB), 404);
        assertProblem(send(HttpRequest.newBuilder(uri("/api/jobs/" + id)).DELETE(), BOB), 404);

        JsonNode status = JSON.readTree(get("/api/jobs/" + id, ALICE).body());
        assertThat(status.get("state").asString()).isIn("queued", "running");
        assertProblem(get("/api/jobs/" + id, null), 401);
    }

    @Test
    void principalWithAllTheirJobsRunningGets429NamingTheLimitWhileOthersStillStart() throws Exception {
        assertThat(startJob(CAROL).statusCode()).isEqualTo(202);

        HttpResponse<String> second = startJob(CAROL);
        assertProblem(second, 429);
        assertThat(second.headers().firstValue("Retry-After")).isPresent();
        assertThat(JSON.readTree(second.body()).get("detail").asString())
                .contains("studio.security.max-jobs-per-principal=1");

        assertThat(startJob(BOB).statusCode()).isEqualTo(202);
    }

    @Test
    void validJwtSignsInAsItsSubject() throws Exception {
        String token = TestTokens.signed("dave", Instant.now().plusSeconds(300));
        HttpResponse<String> response = get("/api/me", token);
        assertThat(response.statusCode()).isEqualTo(200);
        assertThat(JSON.readTree(response.body()).get("principal").asString()).isEqualTo("dave");
    }

    @Test
    void expiredJwtIsRefused() throws Exception {
        HttpResponse<String> response = get("/api/me", TestTokens.signed("dave", Instant.now().minusSeconds(3600)));
        assertProblem(response, 401);
        assertThat(wwwAuthenticate(response)).startsWith("Bearer").contains("invalid_token");
    }

    @Test
    void forgedJwtIsRefused() throws Exception {
        HttpResponse<String> response = get("/api/me", TestTokens.forged("alice"));
        assertProblem(response, 401);
        assertThat(wwwAuthenticate(response)).startsWith("Bearer").contains("invalid_token");
    }

    @Test
    void liveViewUpgradeWithoutKeyOrTicketIsRefused() throws Exception {
        HttpResponse<String> refused = refusedLiveView("", Map.of());
        assertThat(refused.statusCode()).isEqualTo(401);
        assertThat(refused.headers().firstValue("WWW-Authenticate")).hasValue("Bearer");
        assertThat(refused.headers().firstValue("Content-Type")).hasValueSatisfying(
                type -> assertThat(type).startsWith("application/problem+json"));
    }

    @Test
    void liveViewTicketOpensOneViewOnce() throws Exception {
        HttpResponse<String> issued = send(HttpRequest.newBuilder(uri("/api/preview/tickets"))
                .POST(HttpRequest.BodyPublishers.noBody()), ALICE);
        assertThat(issued.statusCode()).isEqualTo(200);
        JsonNode ticket = JSON.readTree(issued.body());
        assertThat(ticket.get("expiresInSeconds").asLong()).isEqualTo(30);
        String query = "?ticket=" + ticket.get("ticket").asString();

        openLiveView(query, Map.of()).sendClose(WebSocket.NORMAL_CLOSURE, "done").get(5, TimeUnit.SECONDS);

        assertThat(refusedLiveView(query, Map.of()).statusCode()).isEqualTo(401);
        assertThat(refusedLiveView("?ticket=made-up", Map.of()).statusCode()).isEqualTo(401);
    }

    @Test
    void ticketsAreOnlyForTheSignedIn() throws Exception {
        assertProblem(send(HttpRequest.newBuilder(uri("/api/preview/tickets"))
                .POST(HttpRequest.BodyPublishers.noBody()), null), 401);
    }

    @Test
    void principalWithAllTheirLiveViewsOpenGets429WhileOthersStillOpen() throws Exception {
        openLiveView("", Map.of("Authorization", "Bearer " + CAROL));

        HttpResponse<String> refused = refusedLiveView("", Map.of("Authorization", "Bearer " + CAROL));
        assertThat(refused.statusCode()).isEqualTo(429);
        assertThat(refused.headers().firstValue("Retry-After")).isPresent();

        openLiveView("", Map.of("Authorization", "Bearer " + BOB));
    }

    @Test
    void probesAndTheBareHealthStayOpenWithoutDetails() throws Exception {
        assertThat(get("/actuator/health/liveness", null).statusCode()).isEqualTo(200);
        assertThat(get("/actuator/health/readiness", null).statusCode()).isEqualTo(200);
        HttpResponse<String> health = get("/actuator/health", null);
        assertThat(health.statusCode()).isEqualTo(200);
        assertThat(JSON.readTree(health.body()).get("status").asString()).isEqualTo("UP");
        assertThat(health.body()).doesNotContain("details", "\"member\"", "\"name\"");
        assertProblem(get("/actuator/health/cluster", null), 401);
    }

    @Test
    void metricsAndHealthDetailsNeedAPrincipal() throws Exception {
        assertProblem(get("/actuator/prometheus", null), 401);
        assertThat(get("/actuator/prometheus", ALICE).statusCode()).isEqualTo(200);
        JsonNode health = JSON.readTree(get("/actuator/health", ALICE).body());
        assertThat(health.at("/components/cluster/details/member").asString()).isEqualTo("none");
    }

    @Test
    void refusedSignInsAreCountedWithTheOtherRefusals() throws Exception {
        get("/api/scenes", null);
        assertThat(get("/actuator/prometheus", ALICE).body()).containsPattern("studio_refusals_total\\{[^}]*status=\"401\"");
    }

    @Test
    void editorAndOpenApiDocumentNeedNoKey() throws Exception {
        assertThat(get("/v3/api-docs", null).statusCode()).isEqualTo(200);
        // the editor's files answer 200 in the jar, 404 where the test's class path has no built editor
        for (String path : new String[] {"/", "/index.html", "/assets/index.js", "/swagger-ui.html"}) {
            assertThat(get(path, null).statusCode()).as(path).isNotEqualTo(401);
        }
    }
}

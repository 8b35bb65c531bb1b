package studio.server.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;

import org.junit.jupiter.api.Test;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;

import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * Sign-in off (the default): every request passes as before, as the same nobody; only the health's
 * details (the cluster's name and member addresses among them) are no longer shown to anyone.
 */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT)
class SignInOffTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();
    private static final HttpClient HTTP = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();

    @LocalServerPort
    int port;

    private HttpResponse<String> get(String path) throws Exception {
        return HTTP.send(HttpRequest.newBuilder(URI.create("http://localhost:" + port + path)).build(),
                HttpResponse.BodyHandlers.ofString());
    }

    @Test
    void apiAnswersWithoutAKey() throws Exception {
        assertThat(get("/api/scenes").statusCode()).isEqualTo(200);
        assertThat(get("/actuator/prometheus").statusCode()).isEqualTo(200);
    }

    @Test
    void meSaysNobodyNeedsToSignIn() throws Exception {
        JsonNode me = JSON.readTree(get("/api/me").body());
        assertThat(me.get("principal").asString()).isEmpty();
        assertThat(me.get("signInRequired").asBoolean()).isFalse();
    }

    @Test
    void healthShowsComponentsButNoDetails() throws Exception {
        JsonNode health = JSON.readTree(get("/actuator/health").body());
        assertThat(health.get("status").asString()).isEqualTo("UP");
        assertThat(health.at("/components/cluster/status").asString()).isEqualTo("UP");
        assertThat(health.at("/components/cluster/details").isMissingNode()).isTrue();
        assertThat(health.at("/components/renderMemory/details").isMissingNode()).isTrue();
    }
}

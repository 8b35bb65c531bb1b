package studio.server.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;

import studio.server.Await;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * The time budget over a real socket when the whole image is one tile that takes far longer than
 * the budget: the render stops within a second of its deadline, inside the tile, and says so (a
 * 422 problem, or a failed job).
 */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT, properties = {
        "studio.limits.max-render-time=500ms", "studio.render-threads=1"})
class RenderBudgetApiTest {

    private static final long BUDGET_MILLIS = 500;
    private static final JsonMapper JSON = JsonMapper.builder().build();
    private static final HttpClient HTTP = HttpClient.newBuilder().version(HttpClient.Version.HTTP_1_1)
            .connectTimeout(Duration.ofSeconds(5)).build();
    /** One 16 x 16 tile of several seconds. */
    private static final String ONE_SLOW_TILE = HallOfGlass.scene(16, 256);

    @LocalServerPort
    int port;

    /** The first request of a fresh server (the validator's start, cold code) takes a second or more. */
    @BeforeEach
    void warmUp() throws Exception {
        assertThat(post("/api/render", "{\"image\": {\"width\": 8, \"height\": 6}, \"objects\": []}")
                .statusCode()).isEqualTo(200);
    }

    @Test
    void renderOverItsTimeBudgetInItsOnlyTileGets422WithinASecondOfItsDeadline() throws Exception {
        long start = System.nanoTime();
        HttpResponse<String> response = post("/api/render", ONE_SLOW_TILE);
        long millis = (System.nanoTime() - start) / 1_000_000;

        assertThat(response.statusCode()).as(response.body()).isEqualTo(422);
        assertThat(response.headers().firstValue("Content-Type")).hasValue("application/problem+json");
        JsonNode problem = JSON.readTree(response.body());
        assertThat(problem.get("title").asString()).isEqualTo("Render time budget exceeded");
        assertThat(problem.get("detail").asString()).contains("500 ms").contains("studio.limits.max-render-time");
        assertThat(millis).as("ms until the answer").isLessThan(BUDGET_MILLIS + 1_000);
    }

    @Test
    void jobOverItsTimeBudgetInItsOnlyTileFailsSayingSoWithinASecondOfItsDeadline() throws Exception {
        HttpResponse<String> accepted = post("/api/jobs", ONE_SLOW_TILE);
        assertThat(accepted.statusCode()).as(accepted.body()).isEqualTo(202);
        String id = JSON.readTree(accepted.body()).get("id").asString();

        Await.until("the job to end", 30_000, () -> !status(id).get("state").asString().matches("queued|running"));

        JsonNode status = status(id);
        assertThat(status.get("state").asString()).isEqualTo("failed");
        assertThat(status.get("error").asString()).contains("time budget").contains("500 ms");
        assertThat(status.get("elapsedMillis").asLong()).as("ms the job ran").isLessThan(BUDGET_MILLIS + 1_000);
    }

    private JsonNode status(String id) throws Exception {
        return JSON.readTree(HTTP.send(HttpRequest.newBuilder(uri("/api/jobs/" + id)).build(),
                HttpResponse.BodyHandlers.ofString()).body());
    }

    private URI uri(String path) {
        return URI.create("http://localhost:" + port + path);
    }

    private HttpResponse<String> post(String path, String body) throws Exception {
        return HTTP.send(HttpRequest.newBuilder(uri(path)).header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString(body)).build(), HttpResponse.BodyHandlers.ofString());
    }
}

package studio.server.system;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.util.stream.Stream;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;

import studio.server.Await;
import studio.server.render.RenderService;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * Abusive input over a real socket, against a server with small budgets: each gets a clear
 * problem naming the field (or the budget), nothing is rendered that should not be, no memory stays
 * reserved, and the server still renders afterwards.
 */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT, properties = {
        "studio.limits.max-render-time=400ms", "studio.limits.max-pixel-samples=20000000",
        "studio.render-memory=256MB", "studio.render-threads=2", "studio.jobs.queue=2"})
class AbuseApiTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();
    private static final HttpClient HTTP = HttpClient.newBuilder().version(HttpClient.Version.HTTP_1_1)
            .connectTimeout(Duration.ofSeconds(5)).build();
    private static final String SPHERE = "{\"type\": \"sphere\", \"center\": [0, 1, 0], \"radius\": 1}";
    /** Many seconds of work: glass and a mirror, deep, a million pixels at 16 samples (within the sample budget). */
    private static final String SLOW = """
            {"image": {"width": 1000, "height": 1000}, "render": {"sampler": "jittered", "samples": 16, "maxDepth": 16},
             "objects": [{"type": "sphere", "center": [0, 1, 0], "radius": 1, "material": {"type": "glass", "ior": 1.5}},
                         {"type": "sphere", "center": [1.5, 0.6, -1], "radius": 0.6,
                          "material": {"type": "mirror", "color": "#f0f0f0"}},
                         {"type": "plane"}]}
            """;

    @LocalServerPort
    int port;

    @Autowired
    MemoryBudget memory;

    @Autowired
    RenderService renders;

    @AfterEach
    void serverIsStillHealthyAndHoldsNothing() throws Exception {
        assertThat(get("/actuator/health").body()).contains("\"UP\"");
        HttpResponse<String> tiny = post("/api/render", "{\"image\": {\"width\": 8, \"height\": 6}, \"objects\": ["
                + SPHERE + "]}");
        assertThat(tiny.statusCode()).isEqualTo(200);
        Await.until("every render to end", 30_000, () -> renders.active() == 0);
    }

    static Stream<Arguments> malformedBodies() {
        String deepArrays = "{\"objects\": " + "[".repeat(100_000) + "]".repeat(100_000) + "}";
        String deepObjects = "{\"name\": \"x\", \"render\": " + "{\"a\": ".repeat(50_000) + "1" + "}".repeat(50_000)
                + "}";
        String hugeVector = "{\"camera\": {\"position\": [" + "1, ".repeat(1_000_000) + "1]}, \"objects\": []}";
        String manyObjects = "{\"objects\": [" + (SPHERE + ", ").repeat(100_000) + SPHERE + "]}";
        return Stream.of(
                Arguments.of("nesting 100,000 arrays deep", deepArrays, null),
                Arguments.of("nesting 50,000 objects deep", deepObjects, null),
                Arguments.of("a vector of a million numbers", hugeVector, "camera.position"),
                Arguments.of("100,001 objects", manyObjects, "objects"),
                Arguments.of("a number as a string", "{\"image\": {\"width\": \"64\"}, \"objects\": []}", "image.width"),
                Arguments.of("NaN", "{\"camera\": {\"fov\": NaN}, \"objects\": []}", null),
                Arguments.of("Infinity", "{\"ambient\": Infinity, \"objects\": []}", null),
                Arguments.of("1e400", "{\"camera\": {\"fov\": 1e400}, \"objects\": []}", "camera.fov"),
                Arguments.of("negative zero width", "{\"image\": {\"width\": -0}, \"objects\": []}", "image.width"),
                Arguments.of("a negative size", "{\"objects\": [{\"type\": \"box\", \"size\": [1, -1, 1]}]}",
                        "objects[0].size[1]"),
                Arguments.of("truncated", "{\"objects\": [{\"type\": \"sphere\", \"radius\"", null),
                Arguments.of("a name of 300 characters", "{\"name\": \"" + "n".repeat(300) + "\", \"objects\": []}",
                        "name"),
                Arguments.of("a name with CR/LF and a bad width", "{\"name\": \"a\\r\\nSet-Cookie: x=1\", "
                        + "\"image\": {\"width\": 0}, \"objects\": []}", "image.width"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("malformedBodies")
    void malformedBodyGives400ProblemAndRendersNothing(String what, String body, String field) throws Exception {
        long cancelledBefore = renders.cancelled();
        HttpResponse<String> response = post("/api/render", body);
        assertThat(response.statusCode()).as(what + ": " + abbreviate(response.body())).isEqualTo(400);
        assertThat(response.headers().firstValue("Content-Type")).hasValue("application/problem+json");
        JsonNode problem = JSON.readTree(response.body());
        assertThat(problem.get("errors").isArray()).as(response.body()).isTrue();
        assertThat(problem.get("errors").size()).isPositive();
        if (field != null) {
            assertThat(problem.get("errors").findValuesAsString("field")).as(response.body()).contains(field);
        }
        assertThat(response.body()).doesNotContain("Exception").doesNotContain("\tat ");
        assertThat(renders.cancelled()).isEqualTo(cancelledBefore);
        assertThat(memory.reserved()).isZero();
    }

    @Test
    void renderThatWouldTakeHoursIsRefusedByTheSampleBudget() throws Exception {
        String hours = "{\"image\": {\"width\": 4096, \"height\": 4096}, \"render\": {\"samples\": 1024}, \"objects\": []}";
        HttpResponse<String> response = post("/api/render", hours);
        assertThat(response.statusCode()).isEqualTo(400);
        JsonNode error = JSON.readTree(response.body()).get("errors").get(0);
        assertThat(error.get("field").asString()).isEqualTo("render.samples");
        assertThat(error.get("message").asString()).contains("17,179,869,184").contains("20,000,000")
                .contains("studio.limits.max-pixel-samples");
        // a job is refused the same way, before it exists
        assertThat(post("/api/jobs", hours).statusCode()).isEqualTo(400);
    }

    @Test
    void renderThatCouldNeverFitInMemoryIsRefusedNamingTheImage() throws Exception {
        HttpResponse<String> response = post("/api/render",
                "{\"image\": {\"width\": 4096, \"height\": 4096}, \"render\": {\"samples\": 1}, \"objects\": []}");
        assertThat(response.statusCode()).isEqualTo(400);
        JsonNode error = JSON.readTree(response.body()).get("errors").get(0);
        assertThat(error.get("field").asString()).isEqualTo("image");
        assertThat(error.get("message").asString()).contains("MiB").contains("studio.render-memory");
    }

    @Test
    void renderOverItsTimeBudgetStopsAndSaysSo() throws Exception {
        long start = System.nanoTime();
        HttpResponse<String> response = post("/api/render", SLOW);
        long millis = (System.nanoTime() - start) / 1_000_000;
        assertThat(response.statusCode()).as(response.body()).isEqualTo(422);
        JsonNode problem = JSON.readTree(response.body());
        assertThat(problem.get("title").asString()).isEqualTo("Render time budget exceeded");
        assertThat(problem.get("detail").asString()).contains("400 ms").contains("studio.limits.max-render-time");
        assertThat(millis).as("ms until the answer").isLessThan(10_000);
    }

    @Test
    void jobOverItsTimeBudgetFailsSayingSo() throws Exception {
        HttpResponse<String> accepted = post("/api/jobs", SLOW);
        assertThat(accepted.statusCode()).isEqualTo(202);
        String id = JSON.readTree(accepted.body()).get("id").asString();
        Await.until("the job to end", 30_000, () -> !JSON.readTree(get("/api/jobs/" + id).body()).get("state").asString()
                .matches("queued|running"));
        JsonNode status = JSON.readTree(get("/api/jobs/" + id).body());
        assertThat(status.get("state").asString()).isEqualTo("failed");
        assertThat(status.get("error").asString()).contains("time budget");
        assertThat(get("/api/jobs/" + id + "/image").statusCode()).isEqualTo(409);
    }

    private static String abbreviate(String body) {
        return body.length() > 300 ? body.substring(0, 300) + "..." : body;
    }

    private URI uri(String path) {
        return URI.create("http://localhost:" + port + path);
    }

    private HttpResponse<String> post(String path, String body) throws Exception {
        return HTTP.send(HttpRequest.newBuilder(uri(path)).header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString(body)).build(), HttpResponse.BodyHandlers.ofString());
    }

    private HttpResponse<String> get(String path) throws Exception {
        return HTTP.send(HttpRequest.newBuilder(uri(path)).build(), HttpResponse.BodyHandlers.ofString());
    }
}

package studio.server.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;

import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/** The job API over a real socket: 202 + Location, the event stream, the image, cancel, 404/409/429. */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT, properties = {
        "studio.jobs.concurrent=1", "studio.jobs.queue=1", "studio.render-threads=2"})
class JobApiTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();
    private static final HttpClient HTTP = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();

    @LocalServerPort
    int port;

    private final List<String> started = new ArrayList<>();

    @AfterEach
    void cancelLeftovers() throws Exception {
        for (String id : started) {
            send(HttpRequest.newBuilder(uri("/api/jobs/" + id)).DELETE());
        }
    }

    private URI uri(String path) {
        return URI.create("http://localhost:" + port + path);
    }

    private HttpResponse<String> send(HttpRequest.Builder request) throws Exception {
        return HTTP.send(request.build(), HttpResponse.BodyHandlers.ofString());
    }

    private HttpResponse<String> post(String scene) throws Exception {
        HttpResponse<String> response = send(HttpRequest.newBuilder(uri("/api/jobs"))
                .header("Content-Type", "application/json").POST(HttpRequest.BodyPublishers.ofString(scene)));
        if (response.statusCode() == 202) {
            started.add(JSON.readTree(response.body()).get("id").asString());
        }
        return response;
    }

    @Test
    void startedJobStreamsStatusTilesAndEndThenServesItsImage() throws Exception {
        HttpResponse<String> response = post(JobServiceTest.SMALL);
        assertEquals(202, response.statusCode());
        JsonNode status = JSON.readTree(response.body());
        String id = status.get("id").asString();
        assertEquals("/api/jobs/" + id, response.headers().firstValue("Location").orElseThrow());
        assertEquals("job-test.png", status.get("fileName").asString());

        HttpResponse<InputStream> events = HTTP.send(HttpRequest.newBuilder(uri("/api/jobs/" + id + "/events"))
                .header("Accept", "text/event-stream").build(), HttpResponse.BodyHandlers.ofInputStream());
        assertTrue(events.headers().firstValue("Content-Type").orElseThrow().startsWith("text/event-stream"));
        List<String> names = new ArrayList<>();
        JsonNode end = null;
        try (BufferedReader reader = new BufferedReader(new InputStreamReader(events.body(), StandardCharsets.UTF_8))) {
            String event = null;
            for (String line; (line = reader.readLine()) != null; ) {
                if (line.startsWith("event:")) {
                    event = line.substring(6).trim();
                    names.add(event);
                } else if (line.startsWith("data:") && "end".equals(event)) {
                    end = JSON.readTree(line.substring(5));
                } else if (line.startsWith("data:") && "tile".equals(event)) {
                    JsonNode tile = JSON.readTree(line.substring(5));
                    assertTrue(tile.get("png").asString().startsWith("iVBOR"), "a base64 PNG");
                }
            }
        }
        assertEquals("status", names.get(0));
        assertEquals("end", names.get(names.size() - 1));
        assertTrue(end != null && end.get("state").asString().equals("done"), names.toString());

        HttpResponse<byte[]> image = HTTP.send(HttpRequest.newBuilder(uri("/api/jobs/" + id + "/image")).build(),
                HttpResponse.BodyHandlers.ofByteArray());
        assertEquals(200, image.statusCode());
        assertEquals("image/png", image.headers().firstValue("Content-Type").orElseThrow());
        assertEquals("attachment; filename=\"job-test.png\"",
                image.headers().firstValue("Content-Disposition").orElseThrow());
        assertEquals("done", JSON.readTree(send(HttpRequest.newBuilder(uri("/api/jobs/" + id))).body())
                .get("state").asString());
    }

    @Test
    void invalidSceneIsRefusedBeforeAJobExists() throws Exception {
        HttpResponse<String> response = post("{\"objects\":[{\"type\":\"sphere\",\"radius\":-1}]}");
        assertEquals(400, response.statusCode());
        assertEquals("application/problem+json", response.headers().firstValue("Content-Type").orElseThrow());
        assertEquals("objects[0].radius", JSON.readTree(response.body()).get("errors").get(0).get("field").asString());
    }

    @Test
    void cancelledJobSaysSoAndHasNoImage() throws Exception {
        String id = JSON.readTree(post(JobServiceTest.LARGE).body()).get("id").asString();
        HttpResponse<String> cancel = send(HttpRequest.newBuilder(uri("/api/jobs/" + id)).DELETE());
        assertEquals(202, cancel.statusCode());
        JobServiceTest.await("cancelled", () -> {
            try {
                return JSON.readTree(send(HttpRequest.newBuilder(uri("/api/jobs/" + id))).body())
                        .get("state").asString().equals("cancelled");
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        });
        HttpResponse<String> image = send(HttpRequest.newBuilder(uri("/api/jobs/" + id + "/image")));
        assertEquals(409, image.statusCode());
        assertEquals("application/problem+json", image.headers().firstValue("Content-Type").orElseThrow());
    }

    @Test
    void fullQueueAnswers429WithRetryAfter() throws Exception {
        assertEquals(202, post(JobServiceTest.LARGE).statusCode());
        assertEquals(202, post(JobServiceTest.LARGE).statusCode());
        HttpResponse<String> refused = post(JobServiceTest.SMALL);
        assertEquals(429, refused.statusCode());
        assertTrue(Integer.parseInt(refused.headers().firstValue("Retry-After").orElseThrow()) >= 1);
        assertEquals(429, JSON.readTree(refused.body()).get("status").asInt());
        // refused before the scene is read: an invalid one gets the 429 too, and its 400 on the retry
        assertEquals(429, post("{\"objects\": 5}").statusCode());
    }

    @Test
    void unknownJobIs404Problem() throws Exception {
        for (String path : List.of("/api/jobs/nope", "/api/jobs/nope/image", "/api/jobs/nope/events")) {
            HttpResponse<String> response = send(HttpRequest.newBuilder(uri(path)));
            assertEquals(404, response.statusCode(), path);
        }
        assertEquals(404, send(HttpRequest.newBuilder(uri("/api/jobs/nope")).DELETE()).statusCode());
    }
}

package studio.server.system;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.springframework.boot.builder.SpringApplicationBuilder;
import org.springframework.boot.web.server.context.WebServerApplicationContext;
import org.springframework.context.ConfigurableApplicationContext;

import studio.server.Await;
import studio.server.StudioApplication;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * What SIGTERM does (it closes the application context) while a job runs, another waits, clients
 * watch both, a synchronous render is in flight and a finished job's image has not been fetched yet:
 * every client gets its answer, and the process could exit soon after the grace period.
 */
class GracefulShutdownTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();
    private static final HttpClient HTTP = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
    private static final long GRACE_MILLIS = 2_000;

    private static String scene(int width, int height, int samples) {
        return """
                {"name": "shutdown-test", "image": {"width": %d, "height": %d, "format": "png"},
                 "render": {"sampler": "jittered", "samples": %d},
                 "objects": [{"type": "sphere", "material": {"type": "glass"}}, {"type": "plane"}]}
                """.formatted(width, height, samples);
    }

    private int port;

    private HttpRequest.Builder request(String path) {
        return HttpRequest.newBuilder(URI.create("http://localhost:" + port + path)).timeout(Duration.ofSeconds(30));
    }

    private HttpResponse<String> postJob(String scene) throws Exception {
        return HTTP.send(request("/api/jobs").header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString(scene)).build(), HttpResponse.BodyHandlers.ofString());
    }

    private String startJob(String scene) throws Exception {
        HttpResponse<String> response = postJob(scene);
        assertEquals(202, response.statusCode(), response.body());
        return JSON.readTree(response.body()).get("id").asString();
    }

    private JsonNode status(String id) throws Exception {
        return JSON.readTree(HTTP.send(request("/api/jobs/" + id).build(), HttpResponse.BodyHandlers.ofString()).body());
    }

    /** Reads a job's event stream into a list of lines, in the background. */
    private List<String> watch(String id) {
        List<String> lines = new CopyOnWriteArrayList<>();
        HTTP.sendAsync(request("/api/jobs/" + id + "/events").timeout(Duration.ofMinutes(2)).build(),
                HttpResponse.BodyHandlers.ofLines()).thenAccept(response -> response.body().forEach(lines::add));
        return lines;
    }

    /** The last lines of an event stream, for a failure's message. */
    private static List<String> tail(List<String> lines) {
        List<String> copy = List.copyOf(lines);
        return copy.subList(Math.max(0, copy.size() - 8), copy.size());
    }

    /** The data line after the stream's end event, or null before it. */
    private static String endOf(List<String> lines) {
        for (int i = 0; i + 1 < lines.size(); i++) {
            if (lines.get(i).equals("event:end")) {
                return lines.get(i + 1);
            }
        }
        return null;
    }

    @Test
    void everyClientIsAnsweredBeforeTheServerStops() throws Exception {
        ConfigurableApplicationContext context = new SpringApplicationBuilder(StudioApplication.class).run(
                "--server.port=0", "--studio.jobs.shutdown-grace=" + GRACE_MILLIS + "ms", "--studio.jobs.concurrent=1",
                "--studio.render-threads=1", "--studio.concurrent-renders=1");
        port = ((WebServerApplicationContext) context).getWebServer().getPort();
        Thread closer = new Thread(context::close, "sigterm");
        try {
            drain(closer);
        } finally {
            // a failed check leaves no context closing behind it while later tests start theirs (Spring
            // Boot's logging is one per JVM: a context closing beside a starting one mixed their formats)
            if (closer.getState() == Thread.State.NEW) {
                closer.start();
            }
            closer.join(GRACE_MILLIS + 15_000);
        }
    }

    /** The test itself: {@code closer} closes the context as SIGTERM does. */
    private void drain(Thread closer) throws Exception {
        String finished = startJob(scene(64, 48, 1));
        Await.until("the short job done", 30_000, () -> status(finished).get("state").asString().equals("done"));
        String running = startJob(scene(1024, 768, 256));
        String queued = startJob(scene(64, 48, 1));
        List<String> watchingRunning = watch(running), watchingQueued = watch(queued);
        Await.until("the long job under way", 30_000, () -> status(running).get("progress").asDouble() > 0);
        CompletableFuture<HttpResponse<String>> inFlight = HTTP.sendAsync(request("/api/render")
                .header("Content-Type", "application/json").POST(HttpRequest.BodyPublishers.ofString(
                        scene(1024, 768, 256))).build(), HttpResponse.BodyHandlers.ofString());
        Await.until("the watchers connected", 10_000,
                () -> watchingRunning.contains("event:status") && watchingQueued.contains("event:status"));
        Thread.sleep(300); // the synchronous render has started

        long signal = System.nanoTime();
        closer.start();

        Await.until("the queued job's end, at once", 1_000, () -> endOf(watchingQueued) != null);
        assertEquals("cancelled", JSON.readTree(endOf(watchingQueued).substring(5)).get("state").asString(),
                () -> "the queued job ran: the running job's stream said " + tail(watchingRunning));
        // during the grace period the server still answers: a finished job's image, and new work is refused
        HttpResponse<byte[]> image = HTTP.send(request("/api/jobs/" + finished + "/image").build(),
                HttpResponse.BodyHandlers.ofByteArray());
        assertEquals(200, image.statusCode());
        HttpResponse<String> refused = postJob(scene(64, 48, 1));
        assertEquals(429, refused.statusCode(), refused.body());
        assertTrue(refused.headers().firstValue("Retry-After").isPresent());

        HttpResponse<String> render = inFlight.get(GRACE_MILLIS + 10_000, TimeUnit.MILLISECONDS);
        assertEquals(503, render.statusCode(), render.body());
        assertEquals("application/problem+json", render.headers().firstValue("Content-Type").orElse(""));
        assertTrue(render.headers().firstValue("Retry-After").isPresent());
        Await.until("the running job's end", 10_000, () -> endOf(watchingRunning) != null);
        JsonNode end = JSON.readTree(endOf(watchingRunning).substring(5));
        assertEquals("cancelled", end.get("state").asString());
        assertTrue(end.get("error").asString().contains("shut down"), end.toString());

        closer.join(GRACE_MILLIS + 15_000);
        long millis = (System.nanoTime() - signal) / 1_000_000;
        assertTrue(!closer.isAlive() && millis < GRACE_MILLIS + 6_000, "shutdown took " + millis + " ms");
        assertTrue(millis >= GRACE_MILLIS, "the running renders had their grace period: " + millis + " ms");
    }
}

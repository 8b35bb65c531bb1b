package studio.server.preview;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;

import studio.server.Await;
import studio.server.system.MemoryBudget;
import tools.jackson.databind.JsonNode;

/**
 * Live views under load: views dropped mid-render leave nothing behind, and a live view and a job
 * share the cores (each render has its own workers, and the operating system shares the cores
 * among them): neither waits for the other to finish.
 */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT, properties = {
        "studio.preview.max-sessions=16", "studio.render-threads=2"})
class PreviewLoadTest {

    static final String HEAVY = PreviewApiTest.SCENE.replace("\"samples\": 16",
            "\"samples\": 256, \"sampler\": \"jittered\"");

    @LocalServerPort
    int port;
    @Autowired
    PreviewHandler handler;
    @Autowired
    MemoryBudget memory;

    private static long liveViewThreads() {
        return Thread.getAllStackTraces().keySet().stream()
                .filter(t -> t.getName().startsWith("live-view-")
                        || t.getName().startsWith("ForkJoinPool-")) // a render's workers, not the common pool
                .count();
    }

    @Test
    void twoHundredViewsDroppedMidRenderLeaveNoThreadsAndNoMemory() throws Exception {
        long threadsBefore = liveViewThreads();
        long reservedBefore = memory.reserved();
        for (int round = 0; round < 13; round++) {
            // a closed view gives its slot back when the server sees the close: the next 16 wait for
            // that, or the last of them would find the limit (16) still taken and get 503
            Await.until("the round before's views closed", 20_000, () -> handler.open() == 0);
            List<PreviewClient> views = new ArrayList<>();
            for (int i = 0; i < 16; i++) {
                PreviewClient view = new PreviewClient(port);
                view.send(1, PreviewApiTest.SCENE, 320, 240);
                views.add(view);
            }
            // the first views' renders are under way (their later passes), the last ones' may not have started
            Await.until("a frame on the eighth view", 30_000, () -> !views.get(7).frames.isEmpty());
            views.forEach(PreviewClient::close);
        }
        Await.until("every view closed", 20_000, () -> handler.open() == 0);
        Await.until("the render memory given back", 20_000, () -> memory.reserved() == reservedBefore);
        Await.until("the workers gone", 20_000, () -> liveViewThreads() <= threadsBefore);
        assertEquals(0, handler.open());
    }

    @Test
    void aLiveViewAndAJobShareTheCores() throws Exception {
        HttpClient http = HttpClient.newHttpClient();
        String job = http.send(HttpRequest.newBuilder(URI.create("http://localhost:" + port + "/api/jobs"))
                .header("Content-Type", "application/json").POST(HttpRequest.BodyPublishers.ofString(
                        HEAVY.replace("\"width\": 800, \"height\": 600", "\"width\": 1024, \"height\": 768"))).build(),
                HttpResponse.BodyHandlers.ofString()).body();
        String id = PreviewClient.JSON.readTree(job).get("id").asString();
        URI status = URI.create("http://localhost:" + port + "/api/jobs/" + id);
        try (PreviewClient view = new PreviewClient(port)) {
            Await.until("the job under way", 30_000, () -> progress(http, status) > 0);
            double before = progress(http, status);
            for (int revision = 1; revision <= 10; revision++) {
                long sent = System.nanoTime();
                int frames = view.frames.size();
                view.send(revision, HEAVY.replace("[2, 0.5, 0]", "[2, 0.5, " + revision * 0.1 + "]"), 320, 240);
                Await.until("a frame of revision " + revision, 5_000, () -> view.frames.size() > frames);
                long millis = (System.nanoTime() - sent) / 1_000_000;
                assertTrue(millis < 2_000, "the job froze the live view: first frame after " + millis + " ms");
            }
            Await.until("the job going on while the view renders", 30_000, () -> progress(http, status) > before);
        } finally {
            http.send(HttpRequest.newBuilder(status).DELETE().build(), HttpResponse.BodyHandlers.discarding());
        }
    }

    private static double progress(HttpClient http, URI status) throws Exception {
        JsonNode job = PreviewClient.JSON.readTree(http.send(HttpRequest.newBuilder(status).build(),
                HttpResponse.BodyHandlers.ofString()).body());
        return job.get("progress").asDouble();
    }
}

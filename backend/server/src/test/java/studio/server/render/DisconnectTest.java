package studio.server.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.regex.Pattern;

import io.micrometer.core.instrument.MeterRegistry;
import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;

import studio.server.Await;
import studio.server.job.JobService;
import studio.server.job.JobState;
import studio.server.system.MemoryBudget;

/**
 * Clients that go away in the middle of a synchronous render, over real sockets: the container
 * reports the closed connection as an async error, the render stops at its next tile, and nothing
 * is left behind (no render, no thread, no memory reservation), even after 200 of them.
 */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT, properties = {
        "studio.render-threads=1", "studio.concurrent-renders=2"})
class DisconnectTest {

    /** Minutes of work at 2 threads: only a cancel ends it within the test. */
    private static final String SLOW_SCENE = """
            {"image": {"width": 1024, "height": 768},
             "render": {"sampler": "jittered", "samples": 256, "maxDepth": 8},
             "camera": {"position": [0, 2, 8], "lookAt": [0, 1, 0], "up": [0, 1, 0], "fov": 50},
             "lights": [{"type": "point", "position": [4, 6, 4], "color": "#ffffff"}],
             "objects": [
               {"type": "sphere", "center": [0, 1, 0], "radius": 1, "material": {"type": "glass", "ior": 1.5}},
               {"type": "sphere", "center": [1.5, 0.6, -1], "radius": 0.6, "material": {"type": "mirror", "color": "#f0f0f0"}},
               {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": {"type": "chalk", "color": "#808080"}}
             ]}
            """;

    @LocalServerPort
    int port;

    @Autowired
    RenderService renders;

    @Autowired
    JobService jobs;

    @Autowired
    MemoryBudget memory;

    @Autowired
    MeterRegistry meters;

    @Test
    void aClientThatDisconnectsCancelsItsRender() throws Exception {
        // a 32 x 32 tile of this scene at 256 samples takes well under a second on one thread
        assertDisconnectStopsRenderWithin(SLOW_SCENE, 3_000);
    }

    /** The whole image is one tile of several seconds: the render stops inside it. */
    @Test
    void aClientThatDisconnectsMidTileCancelsItsRenderWithinASecond() throws Exception {
        assertDisconnectStopsRenderWithin(HallOfGlass.scene(16, 256), 1_000);
    }

    private double cancelledInMetrics() {
        return meters.get("studio.render.requests.cancelled").functionCounter().count();
    }

    /** Posts the scene, goes away once its render runs, and checks the render stops soon and gives its memory back. */
    private void assertDisconnectStopsRenderWithin(String scene, long maxMillis) throws Exception {
        long cancelledBefore = renders.cancelled();
        double publishedBefore = cancelledInMetrics();
        try (Socket socket = post(scene)) {
            Await.until("the render to start", 10_000, () -> renders.active() == 1);
            Thread.sleep(200);
        } // the client goes away
        long closed = System.nanoTime();
        Await.until("the render to stop", 10_000, () -> renders.active() == 0);
        long stoppedMillis = (System.nanoTime() - closed) / 1_000_000;
        System.out.printf("disconnect: the render stopped %d ms after its client went away%n", stoppedMillis);
        assertThat(renders.cancelled()).isEqualTo(cancelledBefore + 1);
        assertThat(cancelledInMetrics()).as("studio_render_requests_cancelled_total").isEqualTo(publishedBefore + 1);
        assertThat(stoppedMillis).as("ms from disconnect to the render's end").isLessThan(maxMillis);
        Await.until("the memory to be given back", 5_000, () -> memory.reserved() == 0);
    }

    @Test
    void twoHundredDisconnectsLeaveNoThreadsOrMemoryBehind() throws Exception {
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        // warm up: the container's worker threads and the render threads exist after the first few
        for (int i = 0; i < 5; i++) {
            disconnectDuringRender();
        }
        Await.until("the warm-up renders to stop", 10_000, () -> renders.active() == 0);
        int before = settledThreadCount(threads);
        long cancelledBefore = renders.cancelled();
        for (int i = 0; i < 200; i++) {
            disconnectDuringRender();
        }
        Await.until("every render to stop", 20_000, () -> renders.active() == 0);
        int after = settledThreadCount(threads);
        System.out.printf("disconnect: live threads %d before and %d after 200 disconnects mid-render%n", before, after);
        assertThat(renders.cancelled() - cancelledBefore).isEqualTo(200);
        assertThat(after).as("live threads after 200 disconnects (before: %d)", before).isLessThanOrEqualTo(before + 4);
        Await.until("the memory to be given back", 5_000, () -> memory.reserved() == 0);
    }

    @Test
    void aJobWhoseOnlyEventStreamDisconnectsIsCancelledWithinATile() throws Exception {
        String id;
        try (Socket socket = request("POST", "/api/jobs", SLOW_SCENE)) {
            String response = new String(socket.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            var matcher = Pattern.compile("\"id\"\\s*:\\s*\"([0-9a-f]+)\"").matcher(response);
            assertThat(matcher.find()).as(response).isTrue();
            id = matcher.group(1);
        }
        try (Socket events = request("GET", "/api/jobs/" + id + "/events", null)) {
            BufferedReader reader = new BufferedReader(
                    new InputStreamReader(events.getInputStream(), StandardCharsets.UTF_8));
            for (String line; (line = reader.readLine()) != null && !line.startsWith("event:tile"); ) {
                // status first, then tiles as they finish
            }
        } // the only watcher goes away
        long closed = System.nanoTime();
        Await.until("the job to be cancelled", 10_000, () -> jobs.status(id).state() == JobState.CANCELLED);
        long millis = (System.nanoTime() - closed) / 1_000_000;
        System.out.printf("disconnect: the job was cancelled %d ms after its event stream went away%n", millis);
        assertThat(millis).as("ms from disconnect to the job's end").isLessThan(3_000);
    }

    /** Starts a render, waits until it runs, and drops the connection. */
    private void disconnectDuringRender() throws Exception {
        long cancelled = renders.cancelled();
        try (Socket socket = post(SLOW_SCENE)) {
            Await.until("the render to start", 10_000, () -> renders.active() > 0 || renders.cancelled() > cancelled);
        }
        Await.until("the render to be cancelled", 10_000, () -> renders.cancelled() > cancelled);
    }

    private Socket post(String json) throws IOException {
        return request("POST", "/api/render", json);
    }

    /** Sends one HTTP/1.1 request on a fresh connection (closed by the server after the response). */
    private Socket request(String method, String path, String json) throws IOException {
        Socket socket = new Socket("localhost", port);
        byte[] body = json != null ? json.getBytes(StandardCharsets.UTF_8) : new byte[0];
        OutputStream out = socket.getOutputStream();
        out.write((method + " " + path + " HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n"
                + (json != null ? "Content-Type: application/json\r\nContent-Length: " + body.length + "\r\n" : "")
                + "\r\n").getBytes(StandardCharsets.US_ASCII));
        out.write(body);
        out.flush();
        return socket;
    }

    /** The live thread count once it stops falling (finished pools take a moment to wind down). */
    private static int settledThreadCount(ThreadMXBean threads) throws InterruptedException {
        int last = threads.getThreadCount();
        for (int i = 0; i < 40; i++) {
            Thread.sleep(100);
            int now = threads.getThreadCount();
            if (now >= last && i >= 5) {
                return now;
            }
            last = Math.min(last, now);
        }
        return last;
    }
}

package studio.server.preview;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.net.http.WebSocketHandshakeException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;

import io.micrometer.core.instrument.MeterRegistry;
import io.micrometer.core.instrument.Timer;
import studio.server.Await;
import tools.jackson.databind.JsonNode;

/** The live view over a real WebSocket: refinement, the final frame against POST /api/render, problems, limits. */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT, properties = {
        "studio.preview.max-sessions=3", "studio.render-threads=2"})
class PreviewApiTest {

    static final String SCENE = """
            {"name": "live", "image": {"width": 800, "height": 600, "format": "jpg"},
             "render": {"samples": 16},
             "lights": [{"type": "point", "position": [4, 6, 4]}],
             "objects": [{"type": "sphere", "center": [0, 1, 0], "material": {"type": "glass"}},
                         {"type": "box", "center": [2, 0.5, 0], "size": [1, 1, 1], "material": {"type": "plastic", "color": "#cc3333"}},
                         {"type": "plane"}]}
            """;

    @LocalServerPort
    int port;

    @Autowired
    MeterRegistry metrics;

    @Autowired
    PreviewHandler handler;

    private static int[] pixels(byte[] encoded) throws Exception {
        BufferedImage image = ImageIO.read(new ByteArrayInputStream(encoded));
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }

    private byte[] renderPng(String scene) throws Exception {
        HttpResponse<byte[]> response = HttpClient.newHttpClient().send(HttpRequest.newBuilder(
                        URI.create("http://localhost:" + port + "/api/render")).header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString(scene)).build(), HttpResponse.BodyHandlers.ofByteArray());
        assertEquals(200, response.statusCode());
        return response.body();
    }

    @Test
    void refinesCoarseToFineAndEndsWithExactlyTheRendersPixels() throws Exception {
        try (PreviewClient client = new PreviewClient(port)) {
            client.send(1, SCENE, 320, 240);
            Await.until("the final frame", 30_000, () -> client.lastFrame() != null && client.lastFrame().last());
            List<int[]> sizes = new ArrayList<>();
            int pass = 0;
            for (PreviewClient.Frame frame : client.frames) {
                JsonNode h = frame.header();
                assertEquals(1, h.get("revision").asLong());
                assertTrue(h.get("pass").asInt() > pass, "passes in order");
                pass = h.get("pass").asInt();
                sizes.add(new int[] {h.get("width").asInt(), h.get("samplesPerPixel").asInt()});
                BufferedImage decoded = ImageIO.read(new ByteArrayInputStream(frame.image()));
                assertEquals(h.get("width").asInt(), decoded.getWidth());
                assertEquals(h.get("height").asInt(), decoded.getHeight());
                assertEquals(frame.last() ? "png" : "jpeg", h.get("format").asString());
                assertTrue(h.get("millis").asLong() >= 0);
            }
            assertArrayEquals(new int[] {40, 80, 160, 320, 320}, sizes.stream().mapToInt(s -> s[0]).toArray());
            assertArrayEquals(new int[] {1, 1, 1, 1, 16}, sizes.stream().mapToInt(s -> s[1]).toArray());
            String atViewSize = SCENE.replace("\"width\": 800, \"height\": 600, \"format\": \"jpg\"",
                    "\"width\": 320, \"height\": 240, \"format\": \"png\"");
            assertArrayEquals(pixels(renderPng(atViewSize)), pixels(client.lastFrame().image()),
                    "the final frame is the render, pixel for pixel");
        }
    }

    /** The revision's full-size one-sample frame (pass 4 at a 320x240 view), once it has arrived. */
    private static PreviewClient.Frame oneSampleFrame(PreviewClient client, long revision) {
        for (PreviewClient.Frame frame : client.frames) {
            if (frame.header().get("revision").asLong() == revision && frame.header().get("pass").asInt() == 4) {
                return frame;
            }
        }
        return null;
    }

    @Test
    void anEditRendersAgainOnlyWhatItReachesAndShowsWhatAFreshViewShows() throws Exception {
        // opaque (a pixel that sees glass is rendered every time), and a final pass of seconds, so
        // that the rays counted when the one-sample frame arrives are the one-sample passes'
        String opaque = SCENE.replace("\"glass\"", "\"plastic\"")
                .replace("\"samples\": 16", "\"samples\": 256, \"adaptive\": 0");
        String moved = opaque.replace("\"center\": [2, 0.5, 0]", "\"center\": [2.2, 0.5, 0.1]");
        io.micrometer.core.instrument.Counter rays = metrics.get("studio.rays").tag("kind", "live_view").counter();
        byte[] editedFrame, freshFrame;
        double editedRays, freshRays;
        try (PreviewClient edited = new PreviewClient(port)) {
            edited.send(1, opaque, 320, 240);
            Await.until("the one-sample frame", 30_000, () -> oneSampleFrame(edited, 1) != null);
            double before = rays.count();
            edited.send(2, moved, 320, 240);
            Await.until("the edit's one-sample frame", 30_000, () -> oneSampleFrame(edited, 2) != null);
            editedRays = rays.count() - before;
            editedFrame = oneSampleFrame(edited, 2).image();
        }
        try (PreviewClient fresh = new PreviewClient(port)) {
            double before = rays.count();
            fresh.send(1, moved, 320, 240);
            Await.until("the one-sample frame", 30_000, () -> oneSampleFrame(fresh, 1) != null);
            freshRays = rays.count() - before;
            freshFrame = oneSampleFrame(fresh, 1).image();
        }
        assertArrayEquals(freshFrame, editedFrame, "the same frame, to the byte");
        assertTrue(editedRays > 0 && editedRays < freshRays / 2, "rays " + editedRays + " against " + freshRays);
    }

    @Test
    void passesAreCountedAsLiveViewRendersAndOpenViewsAsSessions() throws Exception {
        Timer liveView = metrics.get("studio.render").tag("kind", "live_view").timer();
        long before = liveView.count();
        try (PreviewClient client = new PreviewClient(port)) {
            client.send(1, SCENE, 64, 48);
            Await.until("the final frame", 30_000, () -> client.lastFrame() != null && client.lastFrame().last());
            assertEquals(before + client.frames.size(), liveView.count(), "one render a pass");
            assertTrue(metrics.get("studio.live_view.sessions").gauge().value() >= 1);
        }
        Await.until("the view's session closed", 5_000,
                () -> metrics.get("studio.live_view.sessions").gauge().value() == 0);
    }

    @Test
    void invalidSceneGetsTheRestProblemAndTheNextRevisionRenders() throws Exception {
        try (PreviewClient client = new PreviewClient(port)) {
            client.send(7, SCENE.replace("\"center\": [0, 1, 0]", "\"center\": [0, 1, 0], \"radius\": -1"), 64, 48);
            Await.until("the problem", 10_000, () -> !client.texts.isEmpty());
            JsonNode message = client.texts.get(0);
            assertEquals(7, message.get("revision").asLong());
            JsonNode problem = message.get("problem");
            assertEquals(400, problem.get("status").asInt());
            assertEquals("objects[0].radius", problem.get("errors").get(0).get("field").asString());
            client.send(8, SCENE, 64, 48);
            Await.until("a final frame of the next revision", 30_000,
                    () -> client.lastFrame() != null && client.lastFrame().last());
            assertEquals(8, client.lastFrame().revision());
            assertTrue(client.frames.stream().noneMatch(f -> f.revision() == 7));
        }
    }

    @Test
    void badMessagesNameTheirFieldAndTheViewStaysOpen() throws Exception {
        try (PreviewClient client = new PreviewClient(port)) {
            // each message replaces the one before, so each waits for its answer
            client.send("{\"revision\": 3, \"scene\": {}, \"width\": 0}");
            Await.until("a problem", 10_000, () -> client.texts.size() == 1);
            client.send("not json");
            Await.until("a problem", 10_000, () -> client.texts.size() == 2);
            client.send("{\"revision\": 4, \"scene\": [1], \"colour\": 1}");
            Await.until("a problem", 10_000, () -> client.texts.size() == 3);
            client.send(5, SCENE, 32, 24);
            Await.until("the frame of revision 5", 30_000, () -> client.lastFrame() != null && client.lastFrame().last());
            client.send(5, SCENE, 32, 24);
            Await.until("a problem", 10_000, () -> client.texts.size() == 4);
            assertEquals("width", client.texts.get(0).get("problem").get("errors").get(0).get("field").asString());
            assertEquals(400, client.texts.get(1).get("problem").get("status").asInt());
            assertTrue(client.texts.get(1).get("revision").isNull());
            List<String> fields = new ArrayList<>();
            client.texts.get(2).get("problem").get("errors").forEach(e -> fields.add(e.get("field").asString()));
            assertEquals(List.of("colour", "scene"), fields.stream().sorted().toList());
            assertEquals("revision", client.texts.get(3).get("problem").get("errors").get(0).get("field").asString());
            assertEquals(null, client.closedWith);
        }
    }

    @Test
    void newerRevisionStopsTheOlderAndNoOlderFrameFollowsANewerOne() throws Exception {
        String heavy = SCENE.replace("\"samples\": 16", "\"samples\": 512, \"sampler\": \"jittered\"");
        try (PreviewClient client = new PreviewClient(port)) {
            client.send(1, heavy, 640, 480);
            Await.until("a frame of revision 1", 30_000, () -> !client.frames.isEmpty());
            for (int revision = 2; revision <= 20; revision++) {
                client.send(revision, heavy.replace("[2, 0.5, 0]", "[2, 0.5, " + revision * 0.01 + "]"), 640, 480);
            }
            client.send(21, SCENE, 160, 120);
            Await.until("the final frame of revision 21", 30_000,
                    () -> client.lastFrame() != null && client.lastFrame().last() && client.lastFrame().revision() == 21);
            long newest = 0;
            for (PreviewClient.Frame frame : client.frames) {
                assertTrue(frame.revision() >= newest, "an older frame after a newer one: " + client.order);
                newest = frame.revision();
            }
            assertFalse(client.frames.stream().anyMatch(f -> f.revision() == 1 && f.last()),
                    "revision 1's final 512-sample pass was stopped");
        }
    }

    @Test
    void aMessageThatBeginsToArriveStopsTheRevisionBeingShown() throws Exception {
        String heavy = SCENE.replace("\"samples\": 16", "\"samples\": 512, \"sampler\": \"jittered\"");
        try (PreviewClient client = new PreviewClient(port)) {
            client.send(1, heavy, 640, 480);
            Await.until("revision 1's full-size one-sample frame", 30_000,
                    () -> client.frames.stream().anyMatch(f -> f.header().get("width").asInt() == 640));
            // revision 1's 512-sample pass renders now, for many seconds, on every render thread
            double rendering = renderThreadsCpuSeconds(Duration.ofSeconds(1));
            client.sendPiece("{\"revision\": 2, \"width\": 160, \"height\": 120, \"scene\": ", false);
            Thread.sleep(300); // it stops within a tile
            double arriving = renderThreadsCpuSeconds(Duration.ofSeconds(1));
            client.sendPiece(SCENE + "}", true);
            Await.until("the final frame of revision 2", 30_000,
                    () -> client.lastFrame().last() && client.lastFrame().revision() == 2);

            // revision 1 renders (on a machine that other work shares, its threads get what is left)
            assertTrue(rendering > 0.1, "revision 1 was rendering: " + rendering + " s of CPU in 1 s");
            assertTrue(arriving < rendering / 4, "while revision 2 arrives, revision 1 no longer renders: " + arriving
                    + " s of CPU in 1 s, against " + rendering);
            assertFalse(client.frames.stream().anyMatch(f -> f.revision() == 1 && f.last()));
        }
    }

    /**
     * The CPU time the render threads (each render's pool, {@code ForkJoinPool-N-worker-M}) take
     * over the given wall time; a thread started meanwhile counts from zero. Not the process's: that
     * counts the other test contexts' threads in this JVM too (0.66 s in 1 s in one full run).
     */
    private static double renderThreadsCpuSeconds(Duration over) throws InterruptedException {
        java.lang.management.ThreadMXBean threads = java.lang.management.ManagementFactory.getThreadMXBean();
        java.util.Map<Long, Long> before = renderThreadCpu(threads);
        Thread.sleep(over.toMillis());
        long spent = 0;
        for (var thread : renderThreadCpu(threads).entrySet()) {
            spent += thread.getValue() - before.getOrDefault(thread.getKey(), 0L);
        }
        return spent / 1e9;
    }

    private static java.util.Map<Long, Long> renderThreadCpu(java.lang.management.ThreadMXBean threads) {
        java.util.Map<Long, Long> cpu = new java.util.HashMap<>();
        for (var info : threads.getThreadInfo(threads.getAllThreadIds())) {
            if (info != null && info.getThreadName().startsWith("ForkJoinPool-")) {
                long nanos = threads.getThreadCpuTime(info.getThreadId());
                if (nanos >= 0) {
                    cpu.put(info.getThreadId(), nanos);
                }
            }
        }
        return cpu;
    }

    @Test
    void viewsBeyondTheLimitAreRefusedWith503() throws Exception {
        // the other tests' views give their slots back when the server sees their closes: wait for that,
        // or one of the 3 views below could find the limit still taken by a view already closed
        Await.until("the other tests' views closed", 20_000, () -> handler.open() == 0);
        List<PreviewClient> open = new ArrayList<>();
        try {
            for (int i = 0; i < 3; i++) {
                open.add(new PreviewClient(port));
            }
            ExecutionException refused = assertThrows(ExecutionException.class, () -> new PreviewClient(port));
            WebSocketHandshakeException handshake = (WebSocketHandshakeException) refused.getCause();
            assertEquals(503, handshake.getResponse().statusCode());
            assertTrue(handshake.getResponse().headers().firstValue("Retry-After").isPresent());
        } finally {
            open.forEach(PreviewClient::close);
        }
        Await.until("a place again", 10_000, () -> {
            try (PreviewClient again = new PreviewClient(port)) {
                return again != null;
            } catch (ExecutionException e) {
                return false;
            }
        });
        assertNotNull(port);
    }
}

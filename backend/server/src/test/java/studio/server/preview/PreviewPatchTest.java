package studio.server.preview;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.util.ArrayList;
import java.util.List;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;

import io.micrometer.core.instrument.MeterRegistry;
import studio.server.Await;
import tools.jackson.databind.JsonNode;

/**
 * The live view takes RFC 6902 patches against the last revision: they render what the whole
 * scene renders, the final frame is the render, an edit renders again only what it reaches, and a
 * patch that cannot be applied gets a problem after which a whole scene renders again.
 */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT, properties = {
        "studio.preview.max-sessions=3", "studio.render-threads=2"})
class PreviewPatchTest {

    private static final String SCENE = PreviewApiTest.SCENE;
    private static final String AT_VIEW_SIZE = "\"width\": 320, \"height\": 240, \"format\": \"png\"";

    @LocalServerPort
    int port;

    @Autowired
    MeterRegistry metrics;

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

    private static PreviewClient.Frame frame(PreviewClient client, long revision, int pass) {
        for (PreviewClient.Frame frame : client.frames) {
            if (frame.revision() == revision && frame.header().get("pass").asInt() == pass) {
                return frame;
            }
        }
        return null;
    }

    private static void awaitFinal(PreviewClient client, long revision) throws Exception {
        Await.until("the final frame of revision " + revision, 30_000, () -> client.lastFrame() != null
                && client.lastFrame().revision() == revision && client.lastFrame().last());
    }

    @Test
    void patchedRevisionsEndWithExactlyTheRenderOfThePatchedScene() throws Exception {
        String edited = SCENE.replace("\"center\": [2, 0.5, 0]", "\"center\": [1.5, 0.5, -0.5]")
                .replace("\"#cc3333\"", "\"#3366cc\"")
                .replace("[{\"type\": \"point\", \"position\": [4, 6, 4]}]",
                        "[{\"type\": \"point\", \"position\": [4, 6, 4]}, {\"type\": \"point\", \"position\": [-3, 3, 5], "
                                + "\"intensity\": 0.4}]");
        try (PreviewClient client = new PreviewClient(port)) {
            client.send(1, SCENE, 320, 240);
            client.sendPatch(2, 1, "[{\"op\": \"replace\", \"path\": \"/objects/1/center\", \"value\": [1.5, 0.5, -0.5]}]",
                    320, 240);
            client.sendPatch(3, 2, "[{\"op\": \"test\", \"path\": \"/objects/1/type\", \"value\": \"box\"},"
                    + "{\"op\": \"replace\", \"path\": \"/objects/1/material/color\", \"value\": \"#3366cc\"},"
                    + "{\"op\": \"add\", \"path\": \"/lights/-\", \"value\": {\"type\": \"point\", \"position\": [-3, 3, 5], "
                    + "\"intensity\": 0.4}}]", 320, 240);
            awaitFinal(client, 3);
            assertTrue(client.texts.isEmpty(), client.texts.toString());
            assertArrayEquals(pixels(renderPng(edited.replace("\"width\": 800, \"height\": 600, \"format\": \"jpg\"",
                    AT_VIEW_SIZE))), pixels(client.lastFrame().image()), "the final frame is the render, pixel for pixel");
        }
    }

    @Test
    void aPatchedEditRendersAgainOnlyWhatItReachesAndShowsWhatAFreshViewShows() throws Exception {
        String opaque = SCENE.replace("\"glass\"", "\"plastic\"").replace("\"samples\": 16", "\"samples\": 256, \"adaptive\": 0");
        String moved = opaque.replace("\"center\": [2, 0.5, 0]", "\"center\": [2.2, 0.5, 0.1]");
        io.micrometer.core.instrument.Counter rays = metrics.get("studio.rays").tag("kind", "live_view").counter();
        byte[] editedFrame, freshFrame;
        double editedRays, freshRays;
        try (PreviewClient edited = new PreviewClient(port)) {
            edited.send(1, opaque, 320, 240);
            Await.until("the one-sample frame", 30_000, () -> frame(edited, 1, 4) != null);
            double before = rays.count();
            edited.sendPatch(2, 1, "[{\"op\": \"replace\", \"path\": \"/objects/1/center\", \"value\": [2.2, 0.5, 0.1]}]",
                    320, 240);
            Await.until("the edit's one-sample frame", 30_000, () -> frame(edited, 2, 4) != null);
            editedRays = rays.count() - before;
            editedFrame = frame(edited, 2, 4).image();
        }
        try (PreviewClient fresh = new PreviewClient(port)) {
            double before = rays.count();
            fresh.send(1, moved, 320, 240);
            Await.until("the one-sample frame", 30_000, () -> frame(fresh, 1, 4) != null);
            freshRays = rays.count() - before;
            freshFrame = frame(fresh, 1, 4).image();
        }
        assertArrayEquals(freshFrame, editedFrame, "the same frame, to the byte");
        assertTrue(editedRays > 0 && editedRays < freshRays / 2, "rays " + editedRays + " against " + freshRays);
    }

    @Test
    void patchesFasterThanFramesAllApplyInOrder() throws Exception {
        try (PreviewClient client = new PreviewClient(port)) {
            client.send(1, SCENE, 320, 240);
            for (int revision = 2; revision <= 30; revision++) {
                client.sendPatch(revision, revision - 1, "[{\"op\": \"replace\", \"path\": \"/objects/1/center/2\", "
                        + "\"value\": " + (revision * 0.01) + "}]", 320, 240);
            }
            awaitFinal(client, 30);
            assertTrue(client.texts.isEmpty(), "every patch applied: " + client.texts);
            String last = SCENE.replace("\"center\": [2, 0.5, 0]", "\"center\": [2, 0.5, 0.3]")
                    .replace("\"width\": 800, \"height\": 600, \"format\": \"jpg\"", AT_VIEW_SIZE);
            assertArrayEquals(pixels(renderPng(last)), pixels(client.lastFrame().image()));
        }
    }

    @Test
    void aPatchThatCannotBeAppliedGetsAProblemAndTheNextWholeSceneRenders() throws Exception {
        StringBuilder tooMany = new StringBuilder("[");
        for (int i = 0; i < 1001; i++) {
            tooMany.append(i > 0 ? "," : "").append("{\"op\": \"test\", \"path\": \"/name\", \"value\": \"live\"}");
        }
        // each: a patch, and the field its problem names
        String[][] refused = {
                {"[{\"op\": \"replace\", \"path\": \"/objects/9/center\", \"value\": [0, 0, 0]}]", "patch[0].path"},
                {"[{\"op\": \"add\", \"path\": \"/objects/0/radius\", \"value\": -1}]", "objects[0].radius"},
                {"[{\"op\": \"move\", \"from\": \"/objects\", \"path\": \"/objects/0/loop\"}]", "patch[0].from"},
                {"[{\"op\": \"remove\", \"path\": \"/objects/0/ce~2nter\"}]", "patch[0].path"},
                {"[{\"op\": \"add\", \"path\": \"/objects/0/center/0\", \"value\": 1}]", "objects[0].center"},
                {"[{\"op\": \"test\", \"path\": \"/name\", \"value\": \"other\"}]", "patch[0].value"},
                {tooMany + "]", "patch"},
                {"{\"op\": \"add\"}", "patch"},
        };
        try (PreviewClient client = new PreviewClient(port)) {
            long revision = 0;
            List<String> fields = new ArrayList<>();
            for (String[] patch : refused) {
                client.send(++revision, SCENE, 160, 120);
                awaitFinal(client, revision);
                long whole = revision;
                client.sendPatch(++revision, whole, patch[0], 160, 120);
                long patched = revision;
                Await.until("the problem of revision " + patched, 30_000,
                        () -> client.texts.stream().anyMatch(t -> t.get("revision").asLong() == patched));
                JsonNode problem = client.texts.get(client.texts.size() - 1).get("problem");
                fields.add(problem.get("errors").get(0).get("field").asString());
                assertEquals(400, problem.get("status").asInt());
            }
            assertEquals(List.of(refused).stream().map(p -> p[1]).toList(), fields);

            // against another revision: the one before, one never sent, one after a problem
            client.send(++revision, SCENE, 160, 120);
            awaitFinal(client, revision);
            long whole = revision;
            client.sendPatch(++revision, whole - 1, "[]", 160, 120);
            client.sendPatch(++revision, 1_000_000, "[]", 160, 120);
            client.sendPatch(++revision, revision - 1, "[]", 160, 120);
            long last = revision;
            Await.until("three problems", 30_000, () -> client.texts.stream().filter(t -> t.get("revision").asLong() > whole)
                    .count() == 3);
            assertTrue(client.texts.stream().filter(t -> t.get("revision").asLong() > whole)
                    .allMatch(t -> t.get("problem").get("errors").get(0).get("field").asString().equals("base")));

            client.send("{\"revision\": " + (++revision) + ", \"base\": " + last + ", \"patch\": [], \"scene\": " + SCENE + "}");
            long both = revision;
            Await.until("the problem of a scene and a patch", 30_000,
                    () -> client.texts.stream().anyMatch(t -> t.get("revision").asLong() == both));

            client.send(++revision, SCENE, 160, 120);
            awaitFinal(client, revision);
            client.sendPatch(++revision, revision - 1, "[]", 160, 120);
            awaitFinal(client, revision);
            assertNull(client.closedWith, "the view stays open");
        }
    }
}

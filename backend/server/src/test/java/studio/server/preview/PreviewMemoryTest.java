package studio.server.preview;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;

import studio.server.Await;
import studio.server.system.MemoryBudget;

/**
 * A live view's message is read on the render memory budget as a request body is: one the budget
 * could never hold is refused with a problem while it arrives, holding nothing after, and the view
 * goes on. What views only keep (their one-sample films) gives way to a render that needs the memory.
 */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT, properties = {
        "studio.render-memory=16MB", "studio.render-threads=1"})
class PreviewMemoryTest {

    @LocalServerPort
    int port;
    @Autowired
    MemoryBudget memory;

    @Test
    void aMessageTheBudgetCouldNeverHoldIsRefusedAndTheViewGoesOn() throws Exception {
        StringBuilder spheres = new StringBuilder();
        for (int i = 0; i < 40_000; i++) { // about 2 MB of JSON, many times that once read
            spheres.append(i == 0 ? "" : ",").append("{\"type\": \"sphere\", \"center\": [").append(i).append(", 0, 0]}");
        }
        try (PreviewClient client = new PreviewClient(port)) {
            client.send(1, "{\"objects\": [" + spheres + "]}", 32, 24);
            Await.until("the refusal", 20_000, () -> !client.texts.isEmpty());
            assertEquals(413, client.texts.get(0).get("problem").get("status").asInt(), client.texts.toString());
            Await.until("its memory given back", 5_000, () -> memory.reserved() == 0);
            client.send(2, PreviewApiTest.SCENE, 32, 24);
            Await.until("the next revision's final frame", 30_000,
                    () -> client.lastFrame() != null && client.lastFrame().last());
            assertEquals(2, client.lastFrame().revision());
            assertTrue(client.closedWith == null, "the view stays open");
        }
        Await.until("nothing held after the view", 5_000, () -> memory.reserved() == 0);
    }

    @Test
    void keptFilmsOfIdleViewsGiveWayToARender() throws Exception {
        String opaque = PreviewApiTest.SCENE.replace("\"glass\"", "\"plastic\"");
        try (PreviewClient first = new PreviewClient(port); PreviewClient second = new PreviewClient(port)) {
            int views = 0, keptPerView = 0;
            for (PreviewClient view : List.of(first, second)) {
                view.send(1, opaque, 256, 192); // each keeps a film of 256x192: about 3.2 MB
                Await.until("the final frame", 30_000, () -> view.lastFrame() != null && view.lastFrame().last());
                int kept = ++views;
                // the final frame goes out before its pass gives its memory back: wait for that, or
                // the next view would find the memory short and rightly take this film back
                Await.until("only the films kept", 5_000, () -> memory.reserved() < kept * 3_300_000L);
                keptPerView = memory.yieldingCount() / kept; // the film, the scene, the next patch's base
            }
            long kept = memory.reserved();
            assertTrue(kept > 6_000_000, "kept " + kept);

            // about 12 MB of 16 (4 MiB + 400 x 300 x 66 bytes): it fits only if the kept films give their memory back
            String big = opaque.replace("\"width\": 800, \"height\": 600, \"format\": \"jpg\"",
                    "\"width\": 400, \"height\": 300, \"format\": \"png\"").replace("\"samples\": 16", "\"samples\": 1");
            HttpResponse<byte[]> response = HttpClient.newHttpClient().send(HttpRequest.newBuilder(
                            URI.create("http://localhost:" + port + "/api/render")).header("Content-Type", "application/json")
                    .POST(HttpRequest.BodyPublishers.ofString(big)).build(), HttpResponse.BodyHandlers.ofByteArray());
            assertEquals(200, response.statusCode(), new String(response.body()));
            assertEquals(keptPerView, memory.yieldingCount(), "the older view's kept film was given back, and no more than needed");

            first.send(2, opaque.replace("[2, 0.5, 0]", "[2.2, 0.5, 0]"), 256, 192);
            Await.until("the next revision's final frame", 30_000,
                    () -> first.lastFrame() != null && first.lastFrame().revision() == 2 && first.lastFrame().last());
        }
        Await.until("nothing held after the views", 5_000, () -> memory.reserved() == 0);
    }
}

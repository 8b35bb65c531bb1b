package studio.server.preview;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;

import studio.server.Await;
import studio.server.system.MemoryBudget;

/**
 * A live view's message is read on the render memory budget as a request body is: one the budget
 * could never hold is refused with a problem while it arrives, holding nothing after, and the view
 * goes on.
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
}

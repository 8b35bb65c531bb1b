package studio.server.preview;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.system.CapturedOutput;
import org.springframework.boot.test.system.OutputCaptureExtension;
import org.springframework.boot.test.web.server.LocalServerPort;

import studio.server.Await;
import studio.server.RawHttp;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * Handshakes the live view refuses answer problems and keep no place: more refusals than places,
 * then as many real views as there are places. A message over the limit closes its view without a
 * fault in the log.
 */
@ExtendWith(OutputCaptureExtension.class)
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT, properties = {
        "studio.preview.max-sessions=2", "studio.render-threads=1", "studio.limits.max-body-bytes=65536"})
class PreviewHandshakeTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();

    @LocalServerPort
    int port;

    @Autowired
    PreviewHandler handler;

    private String upgrade(String method, String extraHeaders) {
        return method + " /api/preview HTTP/1.1\r\nHost: localhost:" + port + "\r\n" + extraHeaders
                + "Connection: close\r\n\r\n";
    }

    private static final String WEBSOCKET = "Upgrade: websocket\r\nConnection: Upgrade\r\n"
            + "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n";

    private static JsonNode problem(RawHttp.Answer answer, int status) {
        assertThat(answer.status()).isEqualTo(status);
        assertThat(answer.header("Content-Type")).startsWith("application/problem+json");
        JsonNode body = JSON.readTree(answer.body());
        assertThat(body.get("status").asInt()).isEqualTo(status);
        assertThat(body.get("instance").asString()).isEqualTo("/api/preview");
        return body;
    }

    @Test
    void refusedHandshakesAnswerProblemsAndGiveTheirPlaceBack() throws Exception {
        for (int i = 0; i < 5; i++) {
            JsonNode plain = problem(RawHttp.exchange(port, upgrade("GET", "")), 400);
            assertThat(plain.get("detail").asString()).contains("Upgrade: websocket");
            JsonNode foreign = problem(RawHttp.exchange(port, upgrade("GET", WEBSOCKET
                    + "Origin: http://evil.example\r\n")), 403);
            assertThat(foreign.get("detail").asString()).contains("Origin");
            problem(RawHttp.exchange(port, upgrade("GET", "Upgrade: websocket\r\nConnection: Upgrade\r\n"
                    + "Sec-WebSocket-Version: 13\r\n")), 400);
        }
        assertThat(handler.open()).isZero();
        List<PreviewClient> views = new ArrayList<>();
        try {
            views.add(new PreviewClient(port));
            views.add(new PreviewClient(port));
            JsonNode full = problem(RawHttp.exchange(port, upgrade("GET", WEBSOCKET)), 503);
            assertThat(full.get("detail").asString()).contains("studio.preview.max-sessions");
        } finally {
            views.forEach(PreviewClient::close);
        }
        Await.until("the places to come back", 10_000, () -> handler.open() == 0);
    }

    @Test
    void aMessageOverTheLimitClosesItsViewWithoutAFault(CapturedOutput output) throws Exception {
        try (PreviewClient client = new PreviewClient(port)) {
            try {
                client.send("{\"revision\": 1, \"scene\": \"" + "x".repeat(1 << 20) + "\"}");
            } catch (java.util.concurrent.ExecutionException closedWhileSending) {
                // the server may close the view before the client has sent the whole message
            }
            Await.until("the view to close", 10_000, () -> client.closedWith != null);
            assertThat(client.closedWith).isEqualTo(1009);
        }
        Await.until("the place to come back", 10_000, () -> handler.open() == 0);
        assertThat(output.getAll()).doesNotContain("NullPointerException").doesNotContain("ERROR");
    }
}

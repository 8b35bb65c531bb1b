package studio.server.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;

/**
 * A body that arrives in pieces is read in the background and its request runs on another thread:
 * it still runs as the principal that signed it, so the job it starts is that principal's.
 */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT, properties = {
        "studio.security.api-keys=alice:alice-key-5d1e,bob:bob-key-9c2a", "studio.render-threads=1"})
class SignInSlowBodyTest {

    private static final String SCENE = "{\"image\": {\"width\": 16, \"height\": 12}, \"objects\": [{\"type\": \"sphere\"}]}";

    @LocalServerPort
    int port;

    /** Sends the head and half the body, waits, sends the rest; the answer's status line and body. */
    private String[] sendInTwoParts(String path, String key) throws Exception {
        byte[] body = SCENE.getBytes(StandardCharsets.UTF_8);
        try (Socket socket = new Socket("localhost", port)) {
            socket.setSoTimeout(10_000);
            OutputStream out = socket.getOutputStream();
            out.write(("POST " + path + " HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\n"
                    + "Authorization: Bearer " + key + "\r\nContent-Length: " + body.length
                    + "\r\nConnection: close\r\n\r\n").getBytes(StandardCharsets.US_ASCII));
            out.write(body, 0, body.length / 2);
            out.flush();
            Thread.sleep(300);
            out.write(body, body.length / 2, body.length - body.length / 2);
            out.flush();
            InputStream in = socket.getInputStream();
            ByteArrayOutputStream answer = new ByteArrayOutputStream();
            in.transferTo(answer);
            String text = answer.toString(StandardCharsets.ISO_8859_1);
            return new String[] {text.substring(0, text.indexOf('\r')), text.substring(text.indexOf("\r\n\r\n") + 4)};
        }
    }

    private int status(String path, String key) throws Exception {
        return HttpClient.newHttpClient().send(HttpRequest.newBuilder(URI.create("http://localhost:" + port + path))
                .header("Authorization", "Bearer " + key).build(), HttpResponse.BodyHandlers.discarding()).statusCode();
    }

    @Test
    void aJobWhoseBodyCameInPiecesBelongsToWhoSentIt() throws Exception {
        String[] answer = sendInTwoParts("/api/jobs", "alice-key-5d1e");
        assertThat(answer[0]).isEqualTo("HTTP/1.1 202 ");
        String id = answer[1].replaceAll("(?s).*\"id\":\"([0-9a-f]+)\".*", "$1");
        assertThat(status("/api/jobs/" + id, "alice-key-5d1e")).isEqualTo(200);
        assertThat(status("/api/jobs/" + id, "bob-key-9c2a")).isEqualTo(404);
    }

    @Test
    void aRenderWhoseBodyCameInPiecesIsAnswered() throws Exception {
        assertThat(sendInTwoParts("/api/render", "alice-key-5d1e")[0]).isEqualTo("HTTP/1.1 200 ");
    }
}

package studio.server.system;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
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

/**
 * Clients that declare a body and send it slowly, or not at all, hold connections, not request
 * threads: with more of them than the server has threads, small renders and health still answer
 * at once, and a slow body is still answered 408 once it falls behind.
 */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT, properties = {
        "server.tomcat.threads.max=6", "server.tomcat.threads.min-spare=2", "studio.render-threads=1",
        "studio.limits.body-grace=2s", "studio.limits.min-body-rate=64KB"})
class SlowUploadTest {

    private static final HttpClient HTTP = HttpClient.newBuilder().version(HttpClient.Version.HTTP_1_1)
            .connectTimeout(Duration.ofSeconds(5)).build();
    private static final String SMALL = "{\"image\": {\"width\": 8, \"height\": 6}, \"objects\": [{\"type\": \"sphere\"}]}";

    @LocalServerPort
    int port;

    private final List<Socket> sockets = new ArrayList<>();

    @AfterEach
    void close() throws IOException {
        for (Socket socket : sockets) {
            socket.close();
        }
    }

    private Socket slowBody(String path, String expect) throws IOException {
        Socket socket = new Socket("localhost", port);
        sockets.add(socket);
        OutputStream out = socket.getOutputStream();
        out.write(("POST " + path + " HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\n"
                + "Content-Length: 1000000\r\n" + expect + "\r\n{").getBytes(StandardCharsets.US_ASCII));
        out.flush();
        return socket;
    }

    private HttpResponse<byte[]> send(HttpRequest.Builder request) throws Exception {
        return HTTP.send(request.timeout(Duration.ofSeconds(2)).build(), HttpResponse.BodyHandlers.ofByteArray());
    }

    @Test
    void slowBodiesHoldNoThreadSoSmallRendersAndHealthAnswerAtOnce() throws Exception {
        for (int i = 0; i < 24; i++) {
            slowBody(i % 2 == 0 ? "/api/render" : "/api/jobs", "");
        }
        Thread.sleep(300); // every slow body has reached the server
        for (int i = 0; i < 5; i++) {
            HttpResponse<byte[]> render = send(HttpRequest.newBuilder(URI.create("http://localhost:" + port
                    + "/api/render")).header("Content-Type", "application/json")
                    .POST(HttpRequest.BodyPublishers.ofString(SMALL)));
            assertThat(render.statusCode()).isEqualTo(200);
            assertThat(send(HttpRequest.newBuilder(URI.create("http://localhost:" + port
                    + "/actuator/health/liveness")).GET()).statusCode()).isEqualTo(200);
        }
    }

    @Test
    void aBodyThatStopsComingIsAnswered408AfterItsGrace() throws Exception {
        Socket socket = slowBody("/api/render", "");
        socket.setSoTimeout(10_000);
        long start = System.nanoTime();
        String answer = firstLine(socket.getInputStream());
        double seconds = (System.nanoTime() - start) / 1e9;
        assertThat(answer).startsWith("HTTP/1.1 408");
        assertThat(seconds).isBetween(1.5, 6.0); // a grace of 2 s, then 1 byte at 64 KiB/s: due at once
    }

    @Test
    void aBodyExpectingContinueIsInvitedEvenWhenReadInTheBackground() throws Exception {
        Socket socket = slowBody("/api/render", "Expect: 100-continue\r\n");
        socket.setSoTimeout(5_000);
        assertThat(firstLine(socket.getInputStream())).startsWith("HTTP/1.1 100");
    }

    private static String firstLine(InputStream in) throws IOException {
        StringBuilder line = new StringBuilder();
        for (int c = in.read(); c >= 0 && c != '\r'; c = in.read()) {
            line.append((char) c);
        }
        return line.toString();
    }
}

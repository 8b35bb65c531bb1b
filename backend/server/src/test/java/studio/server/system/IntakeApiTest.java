package studio.server.system;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.net.SocketTimeoutException;
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
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;

import studio.server.Await;
import studio.server.render.RenderService;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * The memory and time a request body may take, over real sockets against a server with a 64 MiB
 * budget: bodies reserve what arrives, not what they declare; a trickling body gets 408; a scene
 * whose meshes need more memory to build than the budget gets 413 instead of exhausting the heap;
 * the compile's memory passes to the render; the health endpoint shows the budget.
 */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT, properties = {
        "studio.render-memory=64MB", "studio.render-threads=2", "studio.limits.body-grace=1s",
        "studio.limits.min-body-rate=64KB",
        // the health's details, which sign-in shows only to a signed-in caller (docs/security.md)
        "management.endpoint.health.show-details=always"})
class IntakeApiTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();
    private static final HttpClient HTTP = HttpClient.newBuilder().version(HttpClient.Version.HTTP_1_1)
            .connectTimeout(Duration.ofSeconds(5)).build();
    private static final String SMALL = "{\"image\": {\"width\": 8, \"height\": 6}, \"objects\": [{\"type\": \"sphere\"}]}";

    @LocalServerPort
    int port;

    @Autowired
    MemoryBudget memory;

    @Autowired
    RenderService renders;

    private final List<Socket> sockets = new ArrayList<>();

    @AfterEach
    void closeSocketsAndCheckTheServerStillRenders() throws Exception {
        for (Socket socket : sockets) {
            socket.close();
        }
        assertThat(post("/api/render", SMALL).statusCode()).isEqualTo(200);
        Await.until("every render to end", 30_000, () -> renders.active() == 0);
    }

    /** A fan of {@code triangles} triangles over three vertices: two bytes of OBJ text a triangle. */
    private static String fan(int triangles) {
        return "{\"image\": {\"width\": 64, \"height\": 48}, \"objects\": [{\"type\": \"mesh\", \"obj\": "
                + "\"v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1" + " 2 3".repeat(triangles / 2 + 1) + "\"}]}";
    }

    @Test
    void idleBodiesHoldOnlyWhatTheySentSoOthersStillRender() throws Exception {
        // eight clients declare 4 MiB each (32 MiB x 8 bytes a byte would once have been reserved: the budget
        // four times over) and send one byte
        for (int i = 0; i < 8; i++) {
            Socket socket = openBody("/api/render", 4 << 20);
            socket.getOutputStream().write('{');
            socket.getOutputStream().flush();
        }
        Await.until("the idle bodies to be read as far as they came", 10_000,
                () -> memory.reserved() >= 8 * BodyMemory.PER_OBJECT);

        assertThat(memory.reserved()).isLessThan(1 << 20);
        assertThat(post("/api/render", SMALL).statusCode()).isEqualTo(200);
        assertThat(post("/api/jobs", SMALL).statusCode()).isEqualTo(202);
    }

    @Test
    void aTricklingBodyGets408SoonAfterItsGrace() throws Exception {
        Socket socket = openBody("/api/render", 1000);
        OutputStream out = socket.getOutputStream();
        InputStream in = socket.getInputStream();
        socket.setSoTimeout(300);
        long start = System.nanoTime();
        byte[] answer = new byte[4096];
        int n = -1;
        for (int sent = 0; n < 0 && sent < 100; sent++) { // one byte every 300 ms: 30 s at most
            out.write(sent == 0 ? '{' : ' ');
            out.flush();
            try {
                n = in.read(answer);
            } catch (SocketTimeoutException notYet) {
                // no answer yet: send another byte
            }
        }
        double seconds = (System.nanoTime() - start) / 1e9;

        assertThat(n).as("an answer before 30 s").isPositive();
        String response = new String(answer, 0, n, StandardCharsets.UTF_8);
        assertThat(response).startsWith("HTTP/1.1 408").contains("application/problem+json")
                .contains("studio.limits.min-body-rate");
        assertThat(seconds).as("seconds until the answer").isLessThan(5);
    }

    @Test
    void aSceneWhoseMeshesNeedMoreThanTheBudgetToBuildGets413() throws Exception {
        String scene = fan(250_000); // 0.5 MB of text; 80 MB to parse and build, 54 MB to render
        for (String path : new String[] {"/api/render", "/api/jobs"}) {
            HttpResponse<String> response = post(path, scene);

            assertThat(response.statusCode()).as(path + ": " + response.body()).isEqualTo(413);
            assertThat(response.headers().firstValue("Content-Type")).hasValue("application/problem+json");
            assertThat(JSON.readTree(response.body()).get("detail").asString()).contains("64 MiB")
                    .contains("studio.render-memory");
            assertThat(memory.reserved()).isZero();
        }
    }

    @Test
    void aSceneWhoseCompileAndRenderEachFitButNotTogetherRenders() throws Exception {
        String scene = fan(130_000); // 44 MB to read and build, then 30 MB to render: 74 together, over 64 MiB
        HttpResponse<String> rendered = post("/api/render", scene);
        assertThat(rendered.statusCode()).as(rendered.body()).isEqualTo(200);

        HttpResponse<String> accepted = post("/api/jobs", scene);
        assertThat(accepted.statusCode()).as(accepted.body()).isEqualTo(202);
        String id = JSON.readTree(accepted.body()).get("id").asString();
        Await.until("the job to finish", 30_000,
                () -> JSON.readTree(get("/api/jobs/" + id).body()).get("state").asString().equals("done"));
    }

    @Test
    void healthShowsTheRenderMemoryBelowTheStatus() throws Exception {
        MemoryBudget.Reservation held = memory.tryReserve(1000);
        try {
            JsonNode health = JSON.readTree(get("/actuator/health").body());

            assertThat(health.get("status").asString()).isEqualTo("UP");
            JsonNode renderMemory = health.get("components").get("renderMemory");
            assertThat(renderMemory.get("status").asString()).isEqualTo("UP");
            JsonNode details = renderMemory.get("details");
            assertThat(details.get("capacityBytes").asLong()).isEqualTo(64L << 20);
            assertThat(details.get("reservedBytes").asLong()).isGreaterThanOrEqualTo(1000);
            assertThat(details.get("freeBytes").asLong())
                    .isEqualTo(details.get("capacityBytes").asLong() - details.get("reservedBytes").asLong());
        } finally {
            held.close();
        }
    }

    /** A socket that has sent a POST's headers, declaring {@code length} bytes of body, and none of it. */
    private Socket openBody(String path, int length) throws IOException {
        Socket socket = new Socket("localhost", port);
        sockets.add(socket);
        socket.getOutputStream().write(("POST " + path + " HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json"
                + "\r\nContent-Length: " + length + "\r\n\r\n").getBytes(StandardCharsets.US_ASCII));
        socket.getOutputStream().flush();
        return socket;
    }

    private URI uri(String path) {
        return URI.create("http://localhost:" + port + path);
    }

    private HttpResponse<String> post(String path, String body) throws Exception {
        return HTTP.send(HttpRequest.newBuilder(uri(path)).header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString(body)).build(), HttpResponse.BodyHandlers.ofString());
    }

    private HttpResponse<String> get(String path) throws Exception {
        return HTTP.send(HttpRequest.newBuilder(uri(path)).build(), HttpResponse.BodyHandlers.ofString());
    }
}

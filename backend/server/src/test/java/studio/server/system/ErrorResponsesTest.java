package studio.server.system;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;

import org.junit.jupiter.api.Test;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;

import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * Errors that the servlet container or the request parsing meet before a controller does are
 * problems too, never a 500 or Spring Boot's own error body (each found by scripts/fuzz-api.sh).
 * Over a real socket: MockMvc bypasses the container.
 */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT)
class ErrorResponsesTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();
    private static final HttpClient HTTP = HttpClient.newBuilder().version(HttpClient.Version.HTTP_1_1)
            .connectTimeout(Duration.ofSeconds(5)).build();

    @LocalServerPort
    int port;

    private HttpResponse<String> send(String method, String path, String contentType, String body) throws Exception {
        HttpRequest.Builder request = HttpRequest.newBuilder(URI.create("http://localhost:" + port + path))
                .method(method, body == null ? HttpRequest.BodyPublishers.noBody()
                        : HttpRequest.BodyPublishers.ofString(body));
        if (contentType != null) {
            request.header("Content-Type", contentType);
        }
        return HTTP.send(request.build(), HttpResponse.BodyHandlers.ofString());
    }

    private static JsonNode problem(HttpResponse<String> response, int status) {
        assertThat(response.statusCode()).isEqualTo(status);
        assertThat(response.headers().firstValue("Content-Type").orElse("")).startsWith("application/problem+json");
        JsonNode problem = JSON.readTree(response.body());
        assertThat(problem.get("status").asInt()).isEqualTo(status);
        return problem;
    }

    @Test
    void multipartContentTypeWithoutBoundaryIsRefusedAsNotJsonNotAServerError() throws Exception {
        JsonNode problem = problem(send("POST", "/api/render", "multipart/form-data", "{\"objects\": [}"), 415);
        assertThat(problem.get("detail").asString()).contains("application/json");
    }

    @Test
    void multipartContentTypeOnARequestWithoutBodyIsIgnored() throws Exception {
        problem(send("DELETE", "/api/jobs/nope", "multipart/form-data", null), 404);
    }

    @Test
    void wellFormedMultipartBodyIsRefusedAsNotJson() throws Exception {
        String body = "--b\r\nContent-Disposition: form-data; name=\"scene\"\r\n\r\n{}\r\n--b--\r\n";
        JsonNode problem = problem(send("POST", "/api/jobs", "multipart/form-data; boundary=b", body), 415);
        assertThat(problem.get("detail").asString()).contains("application/json");
    }

    @Test
    void queryParameterWithoutNameIsABadRequestNotAServerError() throws Exception {
        JsonNode problem = problem(send("GET", "/api/meshes?=null&file=meshes/torus-knot.obj", null, null), 400);
        assertThat(problem.get("detail").asString()).contains("parameter without a name");
    }

    @Test
    void traceIsRefusedWithAProblem() throws Exception {
        problem(send("TRACE", "/api/render", null, null), 405);
    }

    @Test
    void errorPathAskedForDirectlyIsNotFound() throws Exception {
        problem(send("GET", "/error", null, null), 404);
    }
}

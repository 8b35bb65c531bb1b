package studio.server.system;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.util.stream.Stream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;

import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * A scene is taken only as JSON. A browser posts text/plain, form and multipart bodies to another
 * site without a CORS preflight, so reading those would let any web page start renders here with
 * its visitors' browsers: they get 415, a problem naming the type to send, and nothing is rendered.
 */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT)
class SceneMediaTypeTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();
    private static final HttpClient HTTP = HttpClient.newBuilder().version(HttpClient.Version.HTTP_1_1)
            .connectTimeout(Duration.ofSeconds(5)).build();
    private static final String TINY = "{\"image\": {\"width\": 4, \"height\": 3}, \"render\": {\"samples\": 1}, "
            + "\"objects\": []}";

    @LocalServerPort
    int port;

    private HttpResponse<String> post(String path, String contentType, String body) throws Exception {
        HttpRequest.Builder request = HttpRequest.newBuilder(URI.create("http://localhost:" + port + path))
                .POST(HttpRequest.BodyPublishers.ofString(body));
        if (contentType != null) {
            request.header("Content-Type", contentType);
        }
        return HTTP.send(request.build(), HttpResponse.BodyHandlers.ofString());
    }

    static Stream<Arguments> notJson() {
        return Stream.of("/api/render", "/api/jobs").flatMap(path -> Stream.of(
                "text/plain", "text/plain;charset=UTF-8", "application/xml", "application/x-www-form-urlencoded",
                "multipart/form-data; boundary=b", "application/octet-stream", null)
                .map(type -> Arguments.of(path, type)));
    }

    @ParameterizedTest(name = "{0} as {1}")
    @MethodSource("notJson")
    void refusesAValidSceneSentAsAnythingButJson(String path, String contentType) throws Exception {
        HttpResponse<String> response = post(path, contentType, TINY);
        assertThat(response.statusCode()).as(response.body()).isEqualTo(415);
        assertThat(response.headers().firstValue("Content-Type")).hasValue("application/problem+json");
        assertThat(response.headers().firstValue("Accept").orElse("")).contains("application/json");
        JsonNode problem = JSON.readTree(response.body());
        assertThat(problem.get("status").asInt()).isEqualTo(415);
        assertThat(problem.get("title").asString()).isEqualTo("Unsupported Media Type");
        assertThat(problem.get("detail").asString()).contains("Content-Type: application/json")
                .contains(contentType == null ? "this request has no Content-Type" : "this request's is '" + contentType);
    }

    @ParameterizedTest
    @ValueSource(strings = {"json", "application/json; charset=klingon"})
    void refusesAContentTypeItCannotRead(String contentType) throws Exception {
        HttpResponse<String> response = post("/api/render", contentType, TINY);
        assertThat(response.statusCode()).isEqualTo(415);
        assertThat(JSON.readTree(response.body()).get("detail").asString())
                .endsWith("this request's, '" + contentType + "', cannot be read (a malformed type, or a charset this "
                        + "server does not know)");
    }

    @ParameterizedTest
    @ValueSource(strings = {"application/json", "application/json; charset=utf-8", "application/vnd.studio.scene+json"})
    void takesJsonOfEveryKind(String contentType) throws Exception {
        assertThat(post("/api/render", contentType, TINY).statusCode()).isEqualTo(200);
        assertThat(post("/api/jobs", contentType, TINY).statusCode()).isEqualTo(202);
    }
}

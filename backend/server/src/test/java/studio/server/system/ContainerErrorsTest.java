package studio.server.system;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.stream.Collectors;
import java.util.stream.IntStream;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;

import studio.server.RawHttp;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * Requests the embedded Tomcat refuses itself, most before any servlet runs (in its HTTP parser,
 * or while decoding the path): each answer is an RFC 9457 problem with a detail in the user's
 * words, never Tomcat's HTML error page. Written byte by byte over a real socket: MockMvc bypasses
 * the container, and HTTP client libraries refuse to send most of these.
 */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT)
class ContainerErrorsTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();
    private static final String SCENE = "{\"objects\": []}";

    @LocalServerPort
    int port;

    private static String get(String target, String headers) {
        return "GET " + target + " HTTP/1.1\r\nHost: localhost\r\n" + headers + "Connection: close\r\n\r\n";
    }

    private static String post(String headers, String body) {
        return "POST /api/render HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\n" + headers
                + "Connection: close\r\n\r\n" + body;
    }

    /** The answer, which must be a problem of the given status; returns its detail. */
    private String problem(String request, int status) throws Exception {
        RawHttp.Answer answer = RawHttp.exchange(port, request);
        assertThat(answer.status()).as(answer.body()).isEqualTo(status);
        assertThat(answer.header("Content-Type")).as(answer.body()).startsWith("application/problem+json");
        JsonNode problem = JSON.readTree(answer.body());
        assertThat(problem.get("status").asInt()).isEqualTo(status);
        assertThat(problem.get("title").asString()).isNotBlank();
        String detail = problem.get("detail").asString();
        assertThat(detail).isNotBlank().doesNotContain("Tomcat").doesNotContain("Exception");
        return detail;
    }

    static Stream<Arguments> pathsTomcatCannotDecode() {
        return Stream.of("/api/jobs/%00", "/api/scenes/..%2F..%2Fetc%2Fpasswd", "/api/scenes/a%2Fb", "/api/scenes/a%5Cb",
                "/api/scenes/%zz", "/api/scenes/%4", "/api/../../etc/passwd").map(Arguments::of);
    }

    @ParameterizedTest
    @MethodSource("pathsTomcatCannotDecode")
    void pathTomcatCannotDecodeIsAProblem(String path) throws Exception {
        assertThat(problem(get(path, ""), 400)).startsWith("the path cannot be read");
    }

    @Test
    void headerOverTheSizeLimitIsAProblemNamingTheLimit() throws Exception {
        assertThat(problem(get("/api/scenes", "X-Big: " + "a".repeat(100_000) + "\r\n"), 400))
                .contains("limit of 8192 bytes").contains("server.max-http-request-header-size");
    }

    @Test
    void twelveThousandQueryParametersAreAProblem() throws Exception {
        String query = IntStream.range(0, 12_000).mapToObj(i -> "p" + i + "=1").collect(Collectors.joining("&"));
        assertThat(problem(get("/api/scenes?" + query, ""), 400)).contains("limit of 8192 bytes");
    }

    @Test
    void overlongUrlIsAProblem() throws Exception {
        assertThat(problem(get("/api/scenes/" + "a".repeat(70_000), ""), 400)).contains("limit of 8192 bytes");
    }

    static Stream<Arguments> requestsTheParserRefuses() {
        return Stream.of(
                Arguments.of("a bad method", "G(T /api/scenes HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n", 400),
                Arguments.of("a backslash in the path", get("/api/scenes/a\\b", ""), 400),
                Arguments.of("a space in the path", "GET /api/sce nes HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n", 400),
                Arguments.of("a control character in the path",
                        "GET /api/\u0001 HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n", 400),
                Arguments.of("a header name with a space", get("/api/scenes", "Bad Header: y\r\n"), 400),
                Arguments.of("no Host", "GET /api/scenes HTTP/1.1\r\nConnection: close\r\n\r\n", 400),
                Arguments.of("a path that is not UTF-8", get("/api/scenes/%C3%28", ""), 400),
                Arguments.of("an absolute URL that does not parse",
                        "GET http://[bad/api HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n", 400),
                Arguments.of("a TLS handshake on the plain port", "\u0016\u0003\u0001\u0002\u0000\u0001\u0000\r\n\r\n", 400),
                Arguments.of("two Content-Lengths", post("Content-Length: 2\r\nContent-Length: 3\r\n", "{}"), 400),
                Arguments.of("a Content-Length that is no number", post("Content-Length: abc\r\n", "{}"), 400),
                Arguments.of("a Transfer-Encoding Tomcat does not speak", post("Transfer-Encoding: gzip\r\n", "{}"), 501),
                Arguments.of("an expectation other than 100-continue", post("Content-Length: 2\r\nExpect: foo\r\n", "{}"), 417),
                Arguments.of("HTTP/9.9", "GET /api/scenes HTTP/9.9\r\nHost: x\r\nConnection: close\r\n\r\n", 505),
                Arguments.of("a broken chunk", post("Transfer-Encoding: chunked\r\n", "zz\r\n{}\r\n0\r\n\r\n"), 400),
                Arguments.of("TRACE", "TRACE /api/render HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n", 405),
                Arguments.of("an unknown method", "FOO /api/scenes HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n", 405),
                Arguments.of("a path parameter on an unknown job", get("/api/jobs/x;jsessionid=abc", ""), 404));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("requestsTheParserRefuses")
    void requestTomcatRefusesIsAProblem(String what, String request, int status) throws Exception {
        problem(request, status);
    }

    @Test
    void pathParameterIsIgnoredOnAKnownPath() throws Exception {
        assertThat(RawHttp.exchange(port, get("/api/scenes;jsessionid=abc", "")).status()).isEqualTo(200);
    }

    @Test
    void oversizedBodyExpectingContinueIsRefusedWithoutBeingInvited() throws Exception {
        String head = "POST /api/render HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\n"
                + "Content-Length: 100000000\r\nExpect: 100-continue\r\nConnection: close\r\n\r\n";
        assertThat(RawHttp.firstStatusLine(port, head)).isEqualTo("HTTP/1.1 413");
    }

    @Test
    void bodyExpectingContinueWithinTheLimitIsInvitedAndRead() throws Exception {
        String head = "POST /api/render HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\n"
                + "Content-Length: " + SCENE.length() + "\r\nExpect: 100-continue\r\nConnection: close\r\n\r\n";
        assertThat(RawHttp.firstStatusLine(port, head)).isEqualTo("HTTP/1.1 100");
    }
}

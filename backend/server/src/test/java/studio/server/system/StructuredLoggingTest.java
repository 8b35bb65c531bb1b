package studio.server.system;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.system.CapturedOutput;
import org.springframework.boot.test.system.OutputCaptureExtension;
import org.springframework.boot.test.web.server.LocalServerPort;

import studio.server.Await;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/** With logging.structured.format.console set, every log line, a job's among them, is one JSON object. */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT, properties = {
        "logging.structured.format.console=ecs", "studio.render-threads=1"})
@ExtendWith(OutputCaptureExtension.class)
class StructuredLoggingTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();

    @LocalServerPort
    int port;

    @Test
    void aJobsLogLinesAreJsonObjects(CapturedOutput output) throws Exception {
        HttpResponse<String> accepted = HttpClient.newHttpClient().send(HttpRequest.newBuilder(
                        URI.create("http://localhost:" + port + "/api/jobs")).header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString(MetricsApiTest.SCENE)).build(), HttpResponse.BodyHandlers.ofString());
        assertThat(accepted.statusCode()).isEqualTo(202);
        String id = JSON.readTree(accepted.body()).get("id").asString();
        Await.until("the job's last log line", 30_000, () -> output.getOut().contains("job " + id + " done"));
        List<JsonNode> lines = output.getOut().lines().filter(line -> line.contains(id)).map(JSON::readTree).toList();
        assertThat(lines).hasSize(3);
        assertThat(lines).allSatisfy(line -> {
            assertThat(line.get("log").get("logger").asString()).isEqualTo("studio.jobs");
            assertThat(line.get("log").get("level").asString()).isEqualTo("INFO");
        });
        assertThat(lines.get(0).get("message").asString()).startsWith("job " + id + " accepted: ");
        assertThat(lines.get(2).get("message").asString()).startsWith("job " + id + " done after ");
    }
}

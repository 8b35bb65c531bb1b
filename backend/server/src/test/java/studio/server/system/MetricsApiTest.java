package studio.server.system;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.system.CapturedOutput;
import org.springframework.boot.test.system.OutputCaptureExtension;
import org.springframework.boot.test.web.server.LocalServerPort;

import studio.server.Await;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * What an operator reads: the studio_* metrics at /actuator/prometheus move with the work (a
 * synchronous render, a job, a refusal), and a job's steps are logged one line each.
 */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT, properties = {
        // tests turn metrics export off by default; this one is about it
        "management.prometheus.metrics.export.enabled=true", "studio.render-threads=2",
        "studio.render-memory=64MB"})
@ExtendWith(OutputCaptureExtension.class)
class MetricsApiTest {

    static final String SCENE = """
            {"name": "tiny", "image": {"width": 24, "height": 16}, "render": {"samples": 1, "maxDepth": 2},
             "lights": [{"type": "point", "position": [4, 6, 4]}],
             "objects": [{"type": "sphere", "material": {"type": "plastic", "color": "#cc3333"}}, {"type": "plane"}]}
            """;

    private static final HttpClient HTTP = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
    private static final JsonMapper JSON = JsonMapper.builder().build();

    @LocalServerPort
    int port;

    private HttpResponse<String> send(HttpRequest.Builder request) throws Exception {
        return HTTP.send(request.timeout(Duration.ofSeconds(30)).build(), HttpResponse.BodyHandlers.ofString());
    }

    private HttpRequest.Builder request(String path) {
        return HttpRequest.newBuilder(URI.create("http://localhost:" + port + path));
    }

    private HttpResponse<String> post(String path, String body) throws Exception {
        return send(request(path).header("Content-Type", "application/json").POST(HttpRequest.BodyPublishers.ofString(body)));
    }

    private String scrape() throws Exception {
        HttpResponse<String> response = send(request("/actuator/prometheus"));
        assertThat(response.statusCode()).isEqualTo(200);
        return response.body();
    }

    /** The value of one sample (a metric name with its labels as written), or 0 if there is none yet. */
    private static double value(String scrape, String sample) {
        Matcher m = Pattern.compile("(?m)^" + Pattern.quote(sample) + " (\\S+)$").matcher(scrape);
        return m.find() ? Double.parseDouble(m.group(1)) : 0;
    }

    @Test
    void publishesTheServicesGaugesWithTheStudioPrefix() throws Exception {
        String scrape = scrape();
        assertThat(value(scrape, "studio_render_memory_capacity_bytes")).isEqualTo(64 * 1024 * 1024);
        assertThat(value(scrape, "studio_render_memory_free_bytes"))
                .isEqualTo(value(scrape, "studio_render_memory_capacity_bytes")
                        - value(scrape, "studio_render_memory_reserved_bytes"));
        assertThat(value(scrape, "studio_cluster_members")).isEqualTo(1);
        assertThat(value(scrape, "studio_render_requests_active")).isZero();
        assertThat(value(scrape, "studio_render_memory_kept")).isZero();
        assertThat(scrape).contains("studio_jobs_queued ", "studio_jobs_running ", "studio_live_view_sessions ",
                "studio_render_requests_active ", "studio_render_requests_cancelled_total ", "studio_render_memory_kept ",
                "# HELP studio_render_seconds ");
        // the JVM's and the web server's own meters come too
        assertThat(scrape).contains("jvm_memory_used_bytes", "http_server_requests_seconds");
    }

    @Test
    void aSynchronousRenderCountsItsTimeAndRays() throws Exception {
        double renders = value(scrape(), "studio_render_seconds_count{kind=\"sync\"}");
        double rays = value(scrape(), "studio_rays_total{kind=\"sync\"}");
        assertThat(post("/api/render", SCENE).statusCode()).isEqualTo(200);
        String scrape = scrape();
        assertThat(value(scrape, "studio_render_seconds_count{kind=\"sync\"}")).isEqualTo(renders + 1);
        // 24x16 camera rays at least, and a shadow ray for most of them
        assertThat(value(scrape, "studio_rays_total{kind=\"sync\"}") - rays).isGreaterThanOrEqualTo(24 * 16);
        assertThat(value(scrape, "studio_render_rays_per_second_max{kind=\"sync\"}")).isPositive();
    }

    @Test
    void refusalsAreCountedByStatus() throws Exception {
        double before400 = value(scrape(), "studio_refusals_total{status=\"400\"}");
        double before404 = value(scrape(), "studio_refusals_total{status=\"404\"}");
        assertThat(post("/api/render", SCENE.replace("\"samples\": 1", "\"samples\": -1")).statusCode()).isEqualTo(400);
        assertThat(post("/api/render", "{").statusCode()).isEqualTo(400);
        assertThat(send(request("/api/jobs/no-such-job")).statusCode()).isEqualTo(404);
        String scrape = scrape();
        assertThat(value(scrape, "studio_refusals_total{status=\"400\"}")).isEqualTo(before400 + 2);
        assertThat(value(scrape, "studio_refusals_total{status=\"404\"}")).isEqualTo(before404 + 1);
    }

    @Test
    void aJobIsTimedAndLoggedOneLineAStep(CapturedOutput output) throws Exception {
        double renders = value(scrape(), "studio_render_seconds_count{kind=\"job\"}");
        HttpResponse<String> accepted = post("/api/jobs", SCENE);
        assertThat(accepted.statusCode()).isEqualTo(202);
        String id = JSON.readTree(accepted.body()).get("id").asString();
        Await.until("the job's end", 30_000, () -> {
            JsonNode status = JSON.readTree(send(request("/api/jobs/" + id)).body());
            return status.get("state").asString().equals("done");
        });
        assertThat(value(scrape(), "studio_render_seconds_count{kind=\"job\"}")).isEqualTo(renders + 1);
        Await.until("the job's last log line", 5_000, () -> output.getOut().contains("job " + id + " done"));
        String out = output.getOut();
        assertThat(out).contains("job " + id + " accepted: 24x16 png, 1 samples per pixel, 2 objects, 1 lights",
                "job " + id + " started after ");
        assertThat(out).containsPattern("job " + id + " done after \\d+ ms, [0-9.]+ M rays/s, \\d+ bytes of image/png");
    }
}

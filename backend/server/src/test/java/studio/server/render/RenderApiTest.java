package studio.server.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.hamcrest.Matchers.containsInAnyOrder;
import static org.hamcrest.Matchers.containsString;
import static org.hamcrest.Matchers.hasItem;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.get;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.post;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.content;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.header;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.jsonPath;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.status;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.test.web.server.LocalServerPort;
import org.springframework.boot.webmvc.test.autoconfigure.AutoConfigureMockMvc;
import org.springframework.http.HttpHeaders;
import org.springframework.http.MediaType;
import org.springframework.test.web.servlet.MockMvc;
import org.springframework.test.web.servlet.MvcResult;

import studio.server.AsyncMvc;
import tools.jackson.databind.json.JsonMapper;

/**
 * The HTTP API end to end: MockMvc through the whole application (filters, advice, converters),
 * and a real server on a random port where only a socket shows the behaviour (chunked bodies,
 * raw headers).
 */
@SpringBootTest(webEnvironment = SpringBootTest.WebEnvironment.RANDOM_PORT, properties = {
        "studio.limits.max-body-bytes=" + RenderApiTest.MAX_BODY_BYTES,
        "studio.render-threads=2"})
@AutoConfigureMockMvc
class RenderApiTest {

    static final int MAX_BODY_BYTES = 4096;

    /** 16x12, one sample: renders in milliseconds. */
    static final String TINY_SCENE = """
            {
              "name": "tiny",
              "image": { "width": 16, "height": 12 },
              "camera": { "position": [0, 1.5, 5], "lookAt": [0, 0.8, 0] },
              "render": { "samples": 1, "maxDepth": 2 },
              "objects": [
                { "type": "sphere", "material": { "type": "plastic", "color": "#cc3333" } },
                { "type": "plane" }
              ]
            }
            """;

    private static final JsonMapper JSON = JsonMapper.builder().build();
    private static final HttpClient HTTP = HttpClient.newBuilder().version(HttpClient.Version.HTTP_1_1)
            .connectTimeout(Duration.ofSeconds(5)).build();

    @Autowired
    MockMvc mvc;

    @Autowired
    org.springframework.context.ApplicationContext context;

    @LocalServerPort
    int port;

    private MvcResult render(String scene) throws Exception {
        return AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content(scene)).andReturn();
    }

    /** The tiny scene with some top-level fields replaced. */
    private static String tinyWith(Map<String, Object> fields) {
        @SuppressWarnings("unchecked")
        Map<String, Object> scene = JSON.readValue(TINY_SCENE, LinkedHashMap.class);
        scene.putAll(fields);
        return JSON.writeValueAsString(scene);
    }

    private static BufferedImage image(byte[] bytes) throws IOException {
        BufferedImage image = ImageIO.read(new ByteArrayInputStream(bytes));
        assertThat(image).as("a readable image").isNotNull();
        return image;
    }

    private void assertRendersTinyScene() throws Exception {
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content(TINY_SCENE))
                .andExpect(status().isOk())
                .andExpect(content().contentType(MediaType.IMAGE_PNG));
    }

    // --- POST /api/render: images ----------------------------------------------------------------

    @Test
    void rendersPngOfTheScenesSizeAsAttachment() throws Exception {
        MvcResult result = AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content(TINY_SCENE))
                .andExpect(status().isOk())
                .andExpect(content().contentType(MediaType.IMAGE_PNG))
                .andExpect(header().string(HttpHeaders.CONTENT_DISPOSITION, "attachment; filename=\"tiny.png\""))
                .andExpect(header().string("X-Image-Size", "16x12"))
                .andExpect(header().exists("X-Render-Millis"))
                .andExpect(header().exists("X-Rays-Per-Second"))
                .andReturn();
        byte[] body = result.getResponse().getContentAsByteArray();
        assertThat(body).startsWith(0x89, 'P', 'N', 'G');
        BufferedImage image = image(body);
        assertThat(image.getWidth()).isEqualTo(16);
        assertThat(image.getHeight()).isEqualTo(12);
    }

    @Test
    void rendersJpegWhenTheSceneAsksForJpg() throws Exception {
        MvcResult result = AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON)
                        .content(tinyWith(Map.of("image", Map.of("width", 20, "height", 10, "format", "jpg")))))
                .andExpect(status().isOk())
                .andExpect(content().contentType(MediaType.IMAGE_JPEG))
                .andExpect(header().string(HttpHeaders.CONTENT_DISPOSITION, "attachment; filename=\"tiny.jpg\""))
                .andReturn();
        byte[] body = result.getResponse().getContentAsByteArray();
        assertThat(body).startsWith(0xff, 0xd8, 0xff);
        assertThat(image(body).getWidth()).isEqualTo(20);
        assertThat(image(body).getHeight()).isEqualTo(10);
    }

    @Test
    void namesTheFileRenderWhenTheSceneHasNoName() throws Exception {
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content("{\"image\":{\"width\":4,"
                        + "\"height\":4},\"render\":{\"samples\":1},"
                        + "\"objects\":[]}"))
                .andExpect(status().isOk())
                .andExpect(header().string(HttpHeaders.CONTENT_DISPOSITION, "attachment; filename=\"render.png\""));
    }

    @Test
    void sanitisesTheNameInContentDisposition() throws Exception {
        String evil = "../../etc/passwd\"\r\nX-Evil: 1";
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content(tinyWith(Map.of("name", evil))))
                .andExpect(status().isOk())
                .andExpect(header().string(HttpHeaders.CONTENT_DISPOSITION,
                        "attachment; filename=\"etc-passwd-X-Evil-1.png\""))
                .andExpect(header().doesNotExist("X-Evil"));
    }

    @Test
    void sanitisedNameNeverReachesTheWireRaw() throws Exception {
        String evil = "../../etc/passwd\"\r\nX-Evil: 1";
        HttpResponse<byte[]> response = send(HttpRequest.newBuilder(uri("/api/render"))
                .header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString(tinyWith(Map.of("name", evil)))).build());
        assertThat(response.statusCode()).isEqualTo(200);
        assertThat(response.headers().firstValue("Content-Disposition"))
                .hasValue("attachment; filename=\"etc-passwd-X-Evil-1.png\"");
        assertThat(response.headers().map().keySet()).noneMatch(name -> name.equalsIgnoreCase("X-Evil"));
        assertThat(String.join("\n", response.headers().allValues("Content-Disposition")))
                .doesNotContain("..").doesNotContain("/").doesNotContain("\r");
    }

    // --- POST /api/render: problems --------------------------------------------------------------

    @Test
    void invalidSceneGives400ProblemNamingEachField() throws Exception {
        String scene = """
                {"image": {"width": 0}, "background": "red",
                 "objects": [{"type": "sphere", "radius": -1}, {"type": "box", "size": [1, 0, 1]}]}
                """;
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content(scene))
                .andExpect(status().isBadRequest())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(400))
                .andExpect(jsonPath("$.title").value("Invalid scene"))
                .andExpect(jsonPath("$.detail").value(containsString("4 problems")))
                .andExpect(jsonPath("$.errors.length()").value(4))
                .andExpect(jsonPath("$.errors[*].field").value(containsInAnyOrder(
                        "image.width", "background", "objects[0].radius", "objects[1].size[1]")))
                .andExpect(jsonPath("$.errors[?(@.field == 'background')].message")
                        .value(hasItem("must be a colour of the form #rrggbb")));
    }

    @Test
    void rendersWithEachNewSamplerAndAdaptiveSampling() throws Exception {
        for (String sampler : List.of("random", "multijittered", "sobol")) {
            AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content(tinyWith(Map.of("render",
                            Map.of("sampler", sampler, "samples", 16, "maxDepth", 2, "adaptive", 0.05)))))
                    .andExpect(status().isOk())
                    .andExpect(content().contentType(MediaType.IMAGE_PNG));
        }
    }

    @Test
    void badAdaptiveThresholdsGive400NamingTheField() throws Exception {
        for (Object bad : List.of(-0.1, 2, "often")) {
            AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON)
                            .content(tinyWith(Map.of("render", Map.of("adaptive", bad)))))
                    .andExpect(status().isBadRequest())
                    .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                    .andExpect(jsonPath("$.status").value(400))
                    .andExpect(jsonPath("$.errors.length()").value(1))
                    .andExpect(jsonPath("$.errors[0].field").value("render.adaptive"));
        }
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON)
                        .content(tinyWith(Map.of("render", Map.of("sampler", "regular", "adaptive", 0.1)))))
                .andExpect(status().isBadRequest())
                .andExpect(jsonPath("$.errors[0].field").value("render.adaptive"))
                .andExpect(jsonPath("$.errors[0].message").value(containsString("regular sampler")));
    }

    @Test
    void coordinatesBeyondTheBoundGive400NamingTheField() throws Exception {
        Map<String, Map<String, Object>> bad = Map.of(
                "objects[0].center[0]", Map.of("objects", List.of(Map.of("type", "sphere", "center", List.of(1e300, 0, 0)))),
                "camera.lookAt[2]", Map.of("camera", Map.of("lookAt", List.of(0, 0, -2e12))),
                "lights[0].position[1]", Map.of("lights", List.of(Map.of("type", "point", "position", List.of(0, 1.5e12, 0)))));
        for (Map.Entry<String, Map<String, Object>> e : bad.entrySet()) {
            AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content(tinyWith(e.getValue())))
                    .andExpect(status().isBadRequest())
                    .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                    .andExpect(jsonPath("$.errors.length()").value(1))
                    .andExpect(jsonPath("$.errors[0].field").value(e.getKey()))
                    .andExpect(jsonPath("$.errors[0].message").value(containsString("1e12")));
        }
    }

    @Test
    void badSoftLightFieldsGive400NamingTheField() throws Exception {
        Map<String, Map<String, Object>> bad = Map.of(
                "lights[0].radius", Map.of("type", "point", "radius", -1),
                "lights[0].size[0]", Map.of("type", "area", "size", List.of(0, 1)),
                "lights[0].lookAt", Map.of("type", "area", "position", List.of(0, 2, 0), "lookAt", List.of(0, 2, 0)));
        for (Map.Entry<String, Map<String, Object>> e : bad.entrySet()) {
            AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON)
                            .content(tinyWith(Map.of("lights", List.of(e.getValue())))))
                    .andExpect(status().isBadRequest())
                    .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                    .andExpect(jsonPath("$.status").value(400))
                    .andExpect(jsonPath("$.errors.length()").value(1))
                    .andExpect(jsonPath("$.errors[0].field").value(e.getKey()));
        }
    }

    @Test
    void rendersUnderSphereAndAreaLights() throws Exception {
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content(tinyWith(Map.of(
                        "lights", List.of(Map.of("type", "point", "position", List.of(2, 4, 3), "radius", 0.5),
                                Map.of("type", "area", "position", List.of(0, 3, 0), "size", List.of(2, 1),
                                        "lookAt", List.of(0, 0, 0), "intensity", 0.5))))))
                .andExpect(status().isOk());
    }

    @Test
    void singleProblemIsTheDetail() throws Exception {
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON)
                        .content("{\"objects\":[{\"type\":\"cone\"}]}"))
                .andExpect(status().isBadRequest())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.errors[0].field").value("objects[0].type"))
                .andExpect(jsonPath("$.errors[0].message").value(containsString("'cone'")))
                .andExpect(jsonPath("$.detail").value(containsString("objects[0].type: unknown type 'cone'")));
    }

    @Test
    void unknownFieldGives400NamingIt() throws Exception {
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON)
                        .content("{\"objects\":[{\"type\":\"sphere\",\"material\":{\"type\":\"chalk\",\"colour\":\"#ffffff\"}}]}"))
                .andExpect(status().isBadRequest())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.errors[0].field").value("objects[0].material.colour"))
                .andExpect(jsonPath("$.errors[0].message").value(containsString("color")));
    }

    @Test
    void limitOverrunGives400NamingTheField() throws Exception {
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON)
                        .content(tinyWith(Map.of("image", Map.of("width", 5000, "height", 10)))))
                .andExpect(status().isBadRequest())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.errors[0].field").value("image.width"))
                .andExpect(jsonPath("$.errors[0].message").value(containsString("4096")));
    }

    @Test
    void malformedJsonGives400WithLineAndColumn() throws Exception {
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content("{\"objects\": [\n{,"))
                .andExpect(status().isBadRequest())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(400))
                .andExpect(jsonPath("$.errors[0].field").value("objects[0]"))
                .andExpect(jsonPath("$.errors[0].message").value(containsString("line 2")));
    }

    @Test
    void emptyBodyGives400() throws Exception {
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON))
                .andExpect(status().isBadRequest())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.errors[0].message").value(containsString("empty")));
    }

    @Test
    void serviceStillRendersAfterBadRequests() throws Exception {
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content("[1, 2"))
                .andExpect(status().isBadRequest());
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON)
                        .content("{\"objects\":[{\"type\":\"sphere\",\"radius\":0}]}"))
                .andExpect(status().isBadRequest());
        assertRendersTinyScene();
    }

    // --- body size limit -------------------------------------------------------------------------

    /** A valid scene padded with spaces to {@code bytes} bytes. */
    private static String sceneOfSize(int bytes) {
        String scene = "{\"objects\":[]}";
        return scene + " ".repeat(bytes - scene.length());
    }

    @Test
    void bodyOverLimitGives413Problem() throws Exception {
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content(sceneOfSize(MAX_BODY_BYTES + 1)))
                .andExpect(status().isContentTooLarge())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(413))
                .andExpect(jsonPath("$.detail").value(containsString(Integer.toString(MAX_BODY_BYTES))));
        assertRendersTinyScene();
    }

    @Test
    void bodyAtLimitIsRead() throws Exception {
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content(
                        tinyWith(Map.of()) + " ".repeat(MAX_BODY_BYTES - tinyWith(Map.of()).length())))
                .andExpect(status().isOk());
    }

    @Test
    void chunkedBodyOverLimitGives413AndServerKeepsAnswering() throws Exception {
        byte[] big = sceneOfSize(16 * MAX_BODY_BYTES).getBytes(StandardCharsets.UTF_8);
        HttpResponse<byte[]> response = send(HttpRequest.newBuilder(uri("/api/render"))
                .header("Content-Type", "application/json")
                // no length known in advance: sent chunked, so only counting while reading can stop it
                .POST(HttpRequest.BodyPublishers.ofInputStream(() -> new ByteArrayInputStream(big))).build());
        assertThat(response.statusCode()).isEqualTo(413);
        assertThat(response.headers().firstValue("Content-Type")).hasValueSatisfying(
                type -> assertThat(type).startsWith("application/problem+json"));
        assertThat(new String(response.body(), StandardCharsets.UTF_8)).contains("\"status\":413");

        HttpResponse<byte[]> after = send(HttpRequest.newBuilder(uri("/api/render"))
                .header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString(TINY_SCENE)).build());
        assertThat(after.statusCode()).isEqualTo(200);
        assertThat(image(after.body()).getWidth()).isEqualTo(16);
    }

    @Test
    void declaredLengthOverLimitGives413OnTheWire() throws Exception {
        HttpResponse<byte[]> response = send(HttpRequest.newBuilder(uri("/api/render"))
                .header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString(sceneOfSize(2 * MAX_BODY_BYTES))).build());
        assertThat(response.statusCode()).isEqualTo(413);
        assertThat(new String(response.body(), StandardCharsets.UTF_8)).contains("\"status\":413");
    }

    // --- everything else -------------------------------------------------------------------------

    @Test
    void unknownApiPathGives404Problem() throws Exception {
        mvc.perform(get("/api/nope"))
                .andExpect(status().isNotFound())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(404));
    }

    @Test
    void healthIsUp() throws Exception {
        mvc.perform(get("/actuator/health"))
                .andExpect(status().isOk())
                .andExpect(jsonPath("$.status").value("UP"));
    }

    /** Its details (the cluster's name and addresses, in a cluster) only for a signed-in caller: SignInApiTest. */
    @Test
    void healthShowsAClusterOfOneThatStartedNoMember() throws Exception {
        mvc.perform(get("/actuator/health/cluster"))
                .andExpect(status().isOk())
                .andExpect(jsonPath("$.status").value("UP"))
                .andExpect(jsonPath("$.details").doesNotExist());
        assertThat(context.getBeanNamesForType(com.hazelcast.core.HazelcastInstance.class)).isEmpty();
    }

    // --- the real server -------------------------------------------------------------------------

    private URI uri(String path) {
        return URI.create("http://localhost:" + port + path);
    }

    private static HttpResponse<byte[]> send(HttpRequest request) throws IOException, InterruptedException {
        return HTTP.send(request, HttpResponse.BodyHandlers.ofByteArray());
    }
}

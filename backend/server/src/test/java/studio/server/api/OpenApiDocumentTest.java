package studio.server.api;

import static org.assertj.core.api.Assertions.assertThat;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.get;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.status;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.webmvc.test.autoconfigure.AutoConfigureMockMvc;
import org.springframework.test.web.servlet.MockMvc;

import studio.server.scene.format.SceneLimits;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * The published OpenAPI document: OpenAPI 3.1, every endpoint with its responses, the scene
 * schema with this server's limits as the request body of both scene operations.
 */
@SpringBootTest(properties = {"studio.limits.max-width=640", "studio.limits.max-objects=50"})
@AutoConfigureMockMvc
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class OpenApiDocumentTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();

    @Autowired
    MockMvc mvc;

    @Autowired
    SceneLimits limits;

    JsonNode doc;

    @BeforeAll
    void fetch() throws Exception {
        byte[] body = mvc.perform(get("/v3/api-docs")).andExpect(status().isOk()).andReturn().getResponse()
                .getContentAsByteArray();
        Files.createDirectories(Path.of("target"));
        Files.write(Path.of("target/openapi.json"), body);
        doc = JSON.readTree(body);
    }

    @Test
    void isOpenApi31WithEveryEndpoint() {
        assertThat(doc.get("openapi").asString()).startsWith("3.1.");
        assertThat(doc.get("info").get("title").asString()).isEqualTo("Ray Studio");
        List<String> operations = new ArrayList<>();
        doc.get("paths").properties().forEach(path -> path.getValue().properties()
                .forEach(op -> operations.add(op.getKey().toUpperCase() + " " + path.getKey())));
        assertThat(operations).containsExactlyInAnyOrder(
                "POST /api/render", "POST /api/jobs", "GET /api/jobs/{id}", "DELETE /api/jobs/{id}",
                "GET /api/jobs/{id}/events", "GET /api/jobs/{id}/image", "GET /api/scenes", "GET /api/scenes/{name}",
                "GET /api/scene-schema", "GET /api/meshes", "GET /api/me", "POST /api/preview/tickets",
                "POST /api/assets", "HEAD /api/assets/{id}", "GET /api/assets/{id}", "GET /actuator/health");
    }

    @Test
    void everyApiOperationMayAnswer401AsAProblemAskingForABearerToken() {
        doc.get("paths").properties().forEach(path -> path.getValue().properties().forEach(op -> {
            JsonNode unauthorized = op.getValue().get("responses").get("401");
            if (path.getKey().startsWith("/api/")) {
                assertThat(unauthorized.get("$ref").asString()).as(path.getKey())
                        .isEqualTo("#/components/responses/Unauthorized");
            } else {
                assertThat(unauthorized).as(path.getKey()).isNull();
            }
        }));
        JsonNode response = doc.get("components").get("responses").get("Unauthorized");
        assertThat(response.get("content").get("application/problem+json").get("schema").get("$ref").asString())
                .isEqualTo("#/components/schemas/Problem");
        assertThat(response.get("headers").get("WWW-Authenticate").get("required").asBoolean()).isTrue();
        JsonNode bearer = doc.get("components").get("securitySchemes").get("bearer");
        assertThat(bearer.get("type").asString()).isEqualTo("http");
        assertThat(bearer.get("scheme").asString()).isEqualTo("bearer");
        assertThat(doc.get("security").toString()).isEqualTo("[{},{\"bearer\":[]}]");
    }

    @Test
    void signInOperationsAnswerTheirSchemas() {
        JsonNode paths = doc.get("paths");
        assertThat(paths.get("/api/me").get("get").get("responses").get("200").get("content").get("application/json")
                .get("schema").get("$ref").asString()).isEqualTo("#/components/schemas/Me");
        JsonNode tickets = paths.get("/api/preview/tickets").get("post").get("responses");
        assertThat(tickets.get("200").get("content").get("application/json").get("schema").get("$ref").asString())
                .isEqualTo("#/components/schemas/PreviewTicket");
        assertThat(tickets.get("429").get("$ref").asString()).isEqualTo("#/components/responses/TooManyTickets");
    }

    @Test
    void sceneOperationsTakeTheSceneSchemaAsTheirRequiredJsonBody() {
        for (String path : List.of("/api/render", "/api/jobs")) {
            JsonNode body = doc.get("paths").get(path).get("post").get("requestBody");
            assertThat(body.get("required").asBoolean()).isTrue();
            assertThat(body.get("content").propertyNames()).containsExactly("application/json");
            assertThat(body.get("content").get("application/json").get("schema").get("$ref").asString())
                    .isEqualTo("#/components/schemas/Scene");
        }
    }

    @Test
    void sceneSchemaIsPublishedAsItIsValidatedWithThisServersLimits() {
        JsonNode schemas = doc.get("components").get("schemas");
        Map<String, Object> expected = ApiSchemas.sceneComponents(limits);
        expected.forEach((name, schema) -> assertThat(schemas.get(name)).as(name)
                .isEqualTo(JSON.readTree(JSON.writeValueAsString(schema))));
        assertThat(schemas.get("Image").get("properties").get("width").get("maximum").asInt()).isEqualTo(640);
        assertThat(schemas.get("Scene").get("properties").get("objects").get("maxItems").asInt()).isEqualTo(50);
        assertThat(doc.toString()).doesNotContain("#/$defs/");
    }

    @Test
    void errorsAreProblemsWithRetryAfterWhereBusy() {
        JsonNode responses = doc.get("components").get("responses");
        assertThat(responses.get("InvalidScene").get("content").get("application/problem+json").get("schema")
                .get("$ref").asString()).isEqualTo("#/components/schemas/InvalidSceneProblem");
        for (String busy : List.of("RenderBusy", "MemoryBusy", "QueueFull")) {
            assertThat(responses.get(busy).get("headers").get("Retry-After").get("$ref").asString())
                    .isEqualTo("#/components/headers/RetryAfter");
        }
        JsonNode paths = doc.get("paths");
        assertThat(paths.get("/api/render").get("post").get("responses").propertyNames())
                .containsExactlyInAnyOrder("200", "400", "401", "408", "413", "415", "422", "503");
        assertThat(paths.get("/api/jobs").get("post").get("responses").propertyNames())
                .containsExactlyInAnyOrder("202", "400", "401", "408", "413", "415", "429", "503");
        assertThat(paths.get("/api/jobs/{id}").get("get").get("responses").get("404").get("$ref").asString())
                .isEqualTo("#/components/responses/JobNotFound");
        assertThat(paths.get("/api/jobs/{id}/image").get("get").get("responses").get("409").get("$ref").asString())
                .isEqualTo("#/components/responses/JobNotDone");
    }

    @Test
    void sceneOperationsAnswer415ProblemNamingTheAcceptedTypes() {
        for (String path : List.of("/api/render", "/api/jobs")) {
            assertThat(doc.get("paths").get(path).get("post").get("responses").get("415").get("$ref").asString())
                    .isEqualTo("#/components/responses/NotJson");
        }
        JsonNode notJson = doc.get("components").get("responses").get("NotJson");
        assertThat(notJson.get("content").get("application/problem+json").get("schema").get("$ref").asString())
                .isEqualTo("#/components/schemas/Problem");
        assertThat(notJson.get("headers").get("Accept").get("description").asString())
                .contains("application/json").contains("application/*+json");
    }
}

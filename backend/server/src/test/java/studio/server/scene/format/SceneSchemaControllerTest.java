package studio.server.scene.format;

import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.get;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.post;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.content;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.jsonPath;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.status;

import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.TestConfiguration;
import org.springframework.boot.webmvc.test.autoconfigure.WebMvcTest;
import org.springframework.context.annotation.Bean;
import org.springframework.http.HttpHeaders;
import org.springframework.http.MediaType;
import org.springframework.test.web.servlet.MockMvc;

/**
 * GET /api/scene-schema as a controller slice: the scene format as JSON Schema with the limits it is
 * given. That the server's configured limits are those limits is OpenApiDocumentTest's.
 */
@WebMvcTest(SceneSchemaController.class)
class SceneSchemaControllerTest {

    private static final MediaType SCHEMA_JSON = MediaType.parseMediaType("application/schema+json");

    @Autowired
    MockMvc mvc;

    /** Limits unlike the defaults, so that the schema shows which ones it was given. */
    @TestConfiguration
    static class Limits {
        @Bean
        SceneLimits sceneLimits() {
            return new SceneLimits(640, 480, 64, 8, 50, 4, 1000, 4096, 1_000_000);
        }
    }

    @Test
    void publishesTheSceneSchemaWithTheGivenLimits() throws Exception {
        mvc.perform(get("/api/scene-schema"))
                .andExpect(status().isOk())
                .andExpect(jsonPath("$.required[0]").value("objects"))
                .andExpect(jsonPath("$.$defs.SphereObject.properties.type.const").value("sphere"))
                .andExpect(jsonPath("$.$defs.Image.properties.width.maximum").value(640))
                .andExpect(jsonPath("$.$defs.Image.properties.height.maximum").value(480));
    }

    @Test
    void answersAsSchemaJsonUnlessPlainJsonIsAsked() throws Exception {
        mvc.perform(get("/api/scene-schema"))
                .andExpect(status().isOk())
                .andExpect(content().contentTypeCompatibleWith(SCHEMA_JSON));
        mvc.perform(get("/api/scene-schema").accept(SCHEMA_JSON))
                .andExpect(content().contentTypeCompatibleWith(SCHEMA_JSON));
        mvc.perform(get("/api/scene-schema").accept(MediaType.APPLICATION_JSON))
                .andExpect(status().isOk())
                .andExpect(content().contentTypeCompatibleWith(MediaType.APPLICATION_JSON));
    }

    @Test
    void askingForAnotherTypeGives406() throws Exception {
        mvc.perform(get("/api/scene-schema").header(HttpHeaders.ACCEPT, "text/html"))
                .andExpect(status().isNotAcceptable());
    }

    @Test
    void postGives405Problem() throws Exception {
        mvc.perform(post("/api/scene-schema").contentType(MediaType.APPLICATION_JSON).content("{}"))
                .andExpect(status().isMethodNotAllowed())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(405));
    }

    @Test
    void unknownPathGives404Problem() throws Exception {
        mvc.perform(get("/api/scene-schemas"))
                .andExpect(status().isNotFound())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(404));
    }
}

package studio.server.api;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.get;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.status;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.webmvc.test.autoconfigure.AutoConfigureMockMvc;
import org.springframework.test.web.servlet.MockMvc;

import tools.jackson.databind.SerializationFeature;
import tools.jackson.databind.json.JsonMapper;

/**
 * The copy of the OpenAPI document the editor's API types are generated from
 * (frontend/src/api/openapi.json, with the default limits) is exactly what the server publishes;
 * the editor's test openapi.test.ts checks that openapi.gen.ts is what that copy generates. After a
 * deliberate change to the API, rewrite the copy with -Dstudio.updateOpenApi=true, then run
 * {@code npm run gen:api} in frontend/.
 */
@SpringBootTest
@AutoConfigureMockMvc
class OpenApiEditorCopyTest {

    static final Path EDITOR_COPY = Path.of("../../frontend/src/api/openapi.json");

    @Autowired
    MockMvc mvc;

    @Test
    void editorCopyIsWhatTheServerPublishes() throws Exception {
        byte[] body = mvc.perform(get("/v3/api-docs")).andExpect(status().isOk()).andReturn().getResponse()
                .getContentAsByteArray();
        JsonMapper json = JsonMapper.builder().enable(SerializationFeature.INDENT_OUTPUT).build();
        String published = json.writeValueAsString(json.readTree(body)) + "\n";
        if (Boolean.getBoolean("studio.updateOpenApi")) {
            Files.writeString(EDITOR_COPY, published, StandardCharsets.UTF_8);
        }
        assertTrue(Files.exists(EDITOR_COPY), "missing " + EDITOR_COPY.toAbsolutePath());
        assertEquals(published, Files.readString(EDITOR_COPY, StandardCharsets.UTF_8),
                "the editor's openapi.json is out of date: run the server tests with -Dstudio.updateOpenApi=true, "
                        + "then npm run gen:api in frontend/");
    }
}

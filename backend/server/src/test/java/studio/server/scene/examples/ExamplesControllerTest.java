package studio.server.scene.examples;

import static org.assertj.core.api.Assertions.assertThat;
import static org.hamcrest.Matchers.containsInAnyOrder;
import static org.hamcrest.Matchers.containsString;
import static org.hamcrest.Matchers.not;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.get;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.content;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.jsonPath;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.status;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.webmvc.test.autoconfigure.WebMvcTest;
import org.springframework.http.MediaType;
import org.springframework.test.web.servlet.MockMvc;
import org.springframework.test.web.servlet.MvcResult;

/** The example scenes and bundled meshes, as the editor's gallery reads them: controller slices. */
@WebMvcTest({ScenesController.class, MeshesController.class})
class ExamplesControllerTest {

    @Autowired
    MockMvc mvc;

    @Test
    void listsEveryExampleScene() throws Exception {
        List<String> expected = ExampleSceneFiles.all().stream().map(ExampleSceneFiles::stem).toList();
        assertThat(expected).isNotEmpty();
        mvc.perform(get("/api/scenes"))
                .andExpect(status().isOk())
                .andExpect(content().contentTypeCompatibleWith(MediaType.APPLICATION_JSON))
                .andExpect(jsonPath("$.length()").value(expected.size()))
                .andExpect(jsonPath("$[*].name").value(containsInAnyOrder(expected.toArray())));
    }

    @Test
    void returnsAnExampleSceneAsItsFile() throws Exception {
        Path file = ExampleSceneFiles.dir().resolve("still-life.json");
        MvcResult result = mvc.perform(get("/api/scenes/still-life"))
                .andExpect(status().isOk())
                .andExpect(content().contentTypeCompatibleWith(MediaType.APPLICATION_JSON))
                .andExpect(jsonPath("$.name").value("still-life"))
                .andReturn();
        assertThat(result.getResponse().getContentAsByteArray()).isEqualTo(Files.readAllBytes(file));
    }

    @Test
    void unknownExampleSceneGives404Problem() throws Exception {
        mvc.perform(get("/api/scenes/nope"))
                .andExpect(status().isNotFound())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.status").value(404))
                .andExpect(jsonPath("$.detail").value(containsString("'nope'")));
    }

    @Test
    void exampleSceneNameInProblemIsSanitised() throws Exception {
        mvc.perform(get("/api/scenes/{name}", "<script>alert(1)</script>"))
                .andExpect(status().isNotFound())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.detail").value(not(containsString("<"))));
    }

    @Test
    void servesAShippedMeshAsObjText() throws Exception {
        String expected = Files.readString(ExampleSceneFiles.dir().resolve("meshes/torus-knot.obj"));
        String body = mvc.perform(get("/api/meshes").param("file", "meshes/torus-knot.obj"))
                .andExpect(status().isOk())
                .andExpect(content().contentTypeCompatibleWith(MediaType.TEXT_PLAIN))
                .andReturn().getResponse().getContentAsString(StandardCharsets.UTF_8);
        assertThat(body).isEqualTo(expected);
    }

    @Test
    void refusesMeshNamesOutsideTheShippedOnes() throws Exception {
        for (String bad : List.of("../application.properties", "meshes/none.obj", "/etc/passwd", "meshes/../mesh.json")) {
            mvc.perform(get("/api/meshes").param("file", bad))
                    .andExpect(status().isNotFound())
                    .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON));
        }
        mvc.perform(get("/api/meshes")).andExpect(status().isBadRequest());
    }
}

package studio.server.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.hamcrest.Matchers.containsString;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.get;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.post;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.content;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.jsonPath;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.status;

import java.io.ByteArrayInputStream;
import java.nio.file.Files;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.webmvc.test.autoconfigure.AutoConfigureMockMvc;
import org.springframework.http.MediaType;
import org.springframework.test.web.servlet.MockMvc;

import studio.server.AsyncMvc;
import studio.server.scene.examples.ExampleSceneFiles;
import tools.jackson.databind.json.JsonMapper;

/** Meshes through the API: shipped meshes by file name, uploaded meshes inline, bad OBJ named by field and line. */
@SpringBootTest(properties = "studio.render-threads=2")
@AutoConfigureMockMvc
class MeshApiTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();

    @Autowired
    MockMvc mvc;

    /** The mesh example, shrunk to a thumbnail. */
    @SuppressWarnings("unchecked")
    private static String meshExample(Map<String, Object> replaceFirstObject) throws Exception {
        Map<String, Object> scene = JSON.readValue(Files.readString(ExampleSceneFiles.dir().resolve("mesh.json")),
                LinkedHashMap.class);
        scene.put("image", Map.of("width", 32, "height", 24));
        scene.put("render", Map.of("samples", 1));
        if (replaceFirstObject != null) {
            List<Object> objects = (List<Object>) scene.get("objects");
            objects.set(0, replaceFirstObject);
        }
        return JSON.writeValueAsString(scene);
    }

    @Test
    void rendersTheMeshExampleWhoseFileShipsWithTheServer() throws Exception {
        byte[] png = AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content(meshExample(null)))
                .andExpect(status().isOk())
                .andReturn().getResponse().getContentAsByteArray();
        assertThat(ImageIO.read(new ByteArrayInputStream(png)).getWidth()).isEqualTo(32);
    }

    @Test
    void rendersAnInlineMesh() throws Exception {
        String tetrahedron = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON)
                        .content(meshExample(Map.of("type", "mesh", "obj", tetrahedron, "scale", 2))))
                .andExpect(status().isOk());
    }

    @Test
    void badObjIsA400NamingTheFieldAndTheLine() throws Exception {
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON)
                        .content(meshExample(Map.of("type", "mesh", "obj", "v 0 0 0\nv 1 0 0\nv 0 1 nan\nf 1 2 3\n"))))
                .andExpect(status().isBadRequest())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.errors[0].field").value("objects[0].obj"))
                .andExpect(jsonPath("$.errors[0].message").value(containsString("line 3")));
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON)
                        .content(meshExample(Map.of("type", "mesh", "file", "../../etc/passwd.obj"))))
                .andExpect(status().isBadRequest())
                .andExpect(jsonPath("$.errors[0].field").value("objects[0].file"));
        mvc.perform(get("/actuator/health")).andExpect(status().isOk());
    }
}

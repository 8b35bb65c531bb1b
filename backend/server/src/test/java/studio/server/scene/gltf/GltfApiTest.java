package studio.server.scene.gltf;

import static org.assertj.core.api.Assertions.assertThat;
import static org.hamcrest.Matchers.containsString;
import static org.hamcrest.Matchers.hasItem;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.get;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.head;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.post;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.content;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.jsonPath;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.status;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.security.MessageDigest;
import java.util.HexFormat;
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

import tools.jackson.databind.node.ObjectNode;

import studio.server.AsyncMvc;

/** glTF models through the API: uploaded, named in a scene, rendered where their transforms put them; bad forms named. */
@SpringBootTest(properties = "studio.render-threads=2")
@AutoConfigureMockMvc
class GltfApiTest {

    private static final int BACKGROUND = 0x20232a;

    @Autowired
    MockMvc mvc;

    private static String id(byte[] bytes) throws Exception {
        return "sha256-" + HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
    }

    private String upload(byte[] bytes, String mediaType) throws Exception {
        return mvc.perform(post("/api/assets").contentType(mediaType).content(bytes))
                .andExpect(status().is2xxSuccessful())
                .andReturn().getResponse().getContentAsString();
    }

    private static String scene(Map<String, Object> model) {
        Map<String, Object> scene = new LinkedHashMap<>();
        scene.put("image", Map.of("width", 33, "height", 33, "format", "png"));
        scene.put("render", Map.of("samples", 1));
        scene.put("camera", Map.of("position", List.of(0, 0, 5), "lookAt", List.of(0, 0, 0), "fov", 60));
        scene.put("objects", List.of(model));
        return TestGltf.JSON.writeValueAsString(scene);
    }

    /**
     * The triangle (0,0,0), (1,0,0), (0,1,0) under a parent moved by (1, 0, 0) and a child scaled by 2,
     * glowing red (emissive: flat), as a glb.
     */
    private static byte[] nestedRedTriangle() {
        ObjectNode gltf = TestGltf.triangle("[{\"translation\": [1, 0, 0], \"children\": [1]},"
                + " {\"scale\": [2, 2, 2], \"mesh\": 0}]");
        ((ObjectNode) gltf.get("materials").get(0)).set("emissiveFactor", TestGltf.JSON.readTree("[1, 0, 0]"));
        return TestGltf.glb(gltf, TestGltf.triangleBuffer());
    }

    @Test
    void anUploadedModelRendersWhereItsTransformsPutIt() throws Exception {
        byte[] glb = nestedRedTriangle();
        upload(glb, "model/gltf-binary");
        // its nodes put it at (1,0,0), (3,0,0), (1,2,0); the object moves it by (-2,-1,0): the lower left half of
        // the square [-1, 1]^2, seen from (0, 0, 5) with a vertical field of view of 60 degrees
        byte[] png = AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON)
                        .content(scene(Map.of("type", "gltf", "asset", id(glb), "position", List.of(-2, -1, 0)))))
                .andExpect(status().isOk())
                .andReturn().getResponse().getContentAsByteArray();
        BufferedImage image = ImageIO.read(new ByteArrayInputStream(png));
        double half = Math.tan(Math.toRadians(30)) * 5;
        assertThat(pixel(image, -0.5, -0.5, half)).isEqualTo(0xff0000);
        assertThat(pixel(image, -0.9, 0.7, half)).isEqualTo(0xff0000);
        assertThat(pixel(image, 0.5, 0.5, half)).isEqualTo(BACKGROUND);
        assertThat(pixel(image, -1.3, -0.5, half)).isEqualTo(BACKGROUND);
        assertThat(pixel(image, -0.5, -1.3, half)).isEqualTo(BACKGROUND);
    }

    /** The colour of the pixel that shows the point (x, y, 0). */
    private static int pixel(BufferedImage image, double x, double y, double half) {
        int column = (int) ((x / half + 1) / 2 * image.getWidth());
        int row = (int) ((1 - y / half) / 2 * image.getHeight());
        return image.getRGB(column, row) & 0xffffff;
    }

    @Test
    void theUploadAnswerListsWhatTheModelHoldsThatIsNotDrawn() throws Exception {
        ObjectNode gltf = TestGltf.triangle("[{\"mesh\": 0, \"skin\": 0}]");
        gltf.set("animations", TestGltf.JSON.readTree("[{\"channels\": [], \"samplers\": []}]"));
        mvc.perform(post("/api/assets").contentType("model/gltf+json").content(TestGltf.bytes(gltf)))
                .andExpect(status().isCreated())
                .andExpect(jsonPath("$.warnings").value(hasItem("animations: the file's animations are not used")))
                .andExpect(jsonPath("$.warnings").value(
                        hasItem("nodes[0]: skins are not applied; the mesh is drawn in its bind pose")));
        mvc.perform(post("/api/assets").contentType("model/gltf+json").content(TestGltf.bytes(gltf)))
                .andExpect(status().isOk())
                .andExpect(jsonPath("$.warnings.length()").value(2));
        mvc.perform(post("/api/assets").contentType("model/obj").content("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"))
                .andExpect(jsonPath("$.warnings.length()").value(0));
    }

    @Test
    void aGltfMayNameItsBufferAsAnotherAsset() throws Exception {
        byte[] buffer = TestGltf.triangleBuffer();
        ObjectNode gltf = TestGltf.triangle();
        ((ObjectNode) gltf.get("buffers").get(0)).put("uri", id(buffer));
        byte[] bytes = TestGltf.bytes(gltf);
        mvc.perform(post("/api/assets").contentType("model/gltf+json").content(bytes))
                .andExpect(status().isBadRequest())
                .andExpect(jsonPath("$.detail").value(containsString("buffers[0].uri: this server has no asset")));
        mvc.perform(head("/api/assets/" + id(bytes))).andExpect(status().isNotFound());
        upload(buffer, "application/octet-stream");
        upload(bytes, "model/gltf+json");
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON)
                        .content(scene(Map.of("type", "gltf", "asset", id(bytes)))))
                .andExpect(status().isOk());
    }

    /** A bad scene: the object, the field its problem names, and a word of the message. */
    private record Bad(Map<String, Object> object, String field, String says) {
    }

    @Test
    void namesEachBadFormAndRendersNothing() throws Exception {
        byte[] obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n".getBytes();
        upload(obj, "model/obj");
        String missing = "sha256-" + "0".repeat(64);
        List<Bad> bads = List.of(
                new Bad(Map.of("type", "gltf", "asset", missing), "objects[0].asset", "upload it"),
                new Bad(Map.of("type", "gltf", "asset", id(obj)), "objects[0].asset", "not a glTF model"),
                new Bad(Map.of("type", "gltf", "asset", "sha256-XYZ"), "objects[0].asset", "asset id"),
                new Bad(Map.of("type", "gltf"), "objects[0]", "\"file\" name or an \"asset\" id"),
                new Bad(Map.of("type", "gltf", "asset", missing, "file", "m.glb"), "objects[0]", "not both"),
                new Bad(Map.of("type", "gltf", "file", "../m.glb"), "objects[0].file", ".glb or .gltf"),
                new Bad(Map.of("type", "gltf", "file", "m.obj"), "objects[0].file", ".glb or .gltf"),
                new Bad(Map.of("type", "gltf", "file", "m.glb"), "objects[0].file", "upload the model"),
                new Bad(Map.of("type", "gltf", "asset", missing, "scale", 0), "objects[0].scale", "greater than 0"),
                new Bad(Map.of("type", "gltf", "asset", missing, "scale", List.of(1, 2, 3)), "objects[0].scale", ""),
                new Bad(Map.of("type", "gltf", "asset", missing, "position", List.of(1, 2)), "objects[0].position", ""),
                new Bad(Map.of("type", "gltf", "asset", missing, "material", Map.of("type", "chalk")),
                        "objects[0].material", ""));
        for (Bad bad : bads) {
            mvc.perform(post("/api/render").contentType(MediaType.APPLICATION_JSON).content(scene(bad.object())))
                    .andExpect(status().isBadRequest())
                    .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                    .andExpect(jsonPath("$.errors[0].field").value(bad.field()))
                    .andExpect(jsonPath("$.errors[0].message").value(containsString(bad.says())));
        }
        mvc.perform(get("/actuator/health")).andExpect(status().isOk());
    }
}

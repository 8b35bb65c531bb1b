package studio.server.asset;

import static org.assertj.core.api.Assertions.assertThat;
import static org.hamcrest.Matchers.containsString;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.get;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.head;
import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.post;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.content;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.header;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.jsonPath;
import static org.springframework.test.web.servlet.result.MockMvcResultMatchers.status;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.springframework.beans.factory.annotation.Autowired;
import org.springframework.boot.test.context.SpringBootTest;
import org.springframework.boot.webmvc.test.autoconfigure.AutoConfigureMockMvc;
import org.springframework.http.MediaType;
import org.springframework.test.web.servlet.MockMvc;

import studio.server.AsyncMvc;
import tools.jackson.databind.json.JsonMapper;

/** POST, HEAD and GET /api/assets, every kind of bad upload, and scenes that name assets. */
@SpringBootTest(properties = {"studio.render-threads=2", "studio.limits.max-triangles=1000",
        "studio.assets.max-pixels=1000000"})
@AutoConfigureMockMvc
class AssetApiTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();

    @Autowired
    MockMvc mvc;

    private String upload(byte[] bytes, String mediaType, int status) throws Exception {
        return mvc.perform(post("/api/assets").contentType(mediaType).content(bytes))
                .andExpect(status().is(status))
                .andExpect(content().contentType(MediaType.APPLICATION_JSON))
                .andExpect(jsonPath("$.id").value(AssetIds.of(bytes)))
                .andExpect(jsonPath("$.bytes").value(bytes.length))
                .andExpect(jsonPath("$.mediaType").value(mediaType))
                .andReturn().getResponse().getContentAsString();
    }

    @Test
    void uploadAnswers201ThenTheSameBytesAnswer200WithTheSameBody() throws Exception {
        byte[] obj = AssetBytes.obj();
        String id = AssetIds.of(obj);
        String first = mvc.perform(post("/api/assets").contentType("model/obj").content(obj))
                .andExpect(status().isCreated())
                .andExpect(header().string("Location", "/api/assets/" + id))
                .andReturn().getResponse().getContentAsString();
        String again = upload(obj, "model/obj", 200);
        assertThat(again).isEqualTo(first);
        assertThat(id).matches("sha256-[0-9a-f]{64}");
    }

    @Test
    void keepsEachKind() throws Exception {
        upload(AssetBytes.png(640, 480), "image/png", 201);
        upload(AssetBytes.jpeg(640, 480), "image/jpeg", 201);
        upload(AssetBytes.glb(), "model/gltf-binary", 201);
        upload(AssetBytes.gltf(), "model/gltf+json", 201);
    }

    @Test
    void headTellsWhetherAnAssetIsKept() throws Exception {
        byte[] png = AssetBytes.png(2, 3);
        upload(png, "image/png", 201);
        mvc.perform(head("/api/assets/" + AssetIds.of(png)))
                .andExpect(status().isOk())
                .andExpect(header().string("Content-Type", "image/png"))
                .andExpect(header().string("Content-Length", String.valueOf(png.length)));
        mvc.perform(head("/api/assets/sha256-" + "0".repeat(64))).andExpect(status().isNotFound());
        mvc.perform(head("/api/assets/sha256-ABC")).andExpect(status().isBadRequest());
    }

    @Test
    void getReturnsTheBytesImmutablyWithTheIdAsETag() throws Exception {
        byte[] jpeg = AssetBytes.jpeg(4, 4);
        upload(jpeg, "image/jpeg", 201);
        String id = AssetIds.of(jpeg);
        mvc.perform(get("/api/assets/" + id))
                .andExpect(status().isOk())
                .andExpect(content().contentType("image/jpeg"))
                .andExpect(content().bytes(jpeg))
                .andExpect(header().string("ETag", "\"" + id + "\""))
                .andExpect(header().string("Cache-Control", containsString("immutable")));
        mvc.perform(get("/api/assets/" + id).header("If-None-Match", "\"" + id + "\""))
                .andExpect(status().isNotModified());
        mvc.perform(get("/api/assets/sha256-" + "1".repeat(64)))
                .andExpect(status().isNotFound())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON));
        mvc.perform(get("/api/assets/sha256-" + "A".repeat(64)))
                .andExpect(status().isBadRequest())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON));
    }

    /** Each bad upload: its bytes, its Content-Type, the status and a word of the detail. */
    private record Bad(String what, byte[] bytes, String mediaType, int status, String detail) {
    }

    @Test
    void refusesBadUploadsKeepingNothing() throws Exception {
        byte[] glb = AssetBytes.glb();
        byte[] wrongVersion = AssetBytes.glb();
        wrongVersion[4] = 1;
        byte[] badChunk = AssetBytes.glb();
        badChunk[16] = 'X';
        List<Bad> bads = List.of(
                new Bad("a truncated glb", Arrays.copyOf(glb, glb.length - 8), "model/gltf-binary", 400, "truncated"),
                new Bad("a glb of version 1", wrongVersion, "model/gltf-binary", 400, "version 1"),
                new Bad("a glb whose first chunk is not JSON", badChunk, "model/gltf-binary", 400, "not JSON"),
                new Bad("a PNG declaring 100,000 x 100,000 pixels", AssetBytes.png(100_000, 100_000), "image/png", 400,
                        "10000000000 pixels"),
                new Bad("a JPEG declaring 60,000 x 60,000 pixels", AssetBytes.jpeg(60_000, 60_000), "image/jpeg", 400,
                        "pixels"),
                new Bad("a truncated PNG", Arrays.copyOf(AssetBytes.png(2, 2), 20), "image/png", 400, "IHDR"),
                new Bad("an OBJ past the triangle limit", AssetBytes.fan(1001), "model/obj", 400, "max-triangles"),
                new Bad("a glTF past the triangle limit", AssetBytes.gltfOf(1001), "model/gltf+json", 400,
                        "draws 1001 triangles; this server's limit is 1000 (studio.limits.max-triangles)"),
                new Bad("a glTF whose accessor runs past its view", AssetBytes.gltfPastItsView(), "model/gltf+json",
                        400, "accessors[0]: its 4 elements run past the end of bufferViews[0]"),
                new Bad("an OBJ that does not parse", "v 0 0 zero\nf 1 2 3\n".getBytes(), "model/obj", 400, "OBJ"),
                new Bad("PNG bytes sent as image/jpeg", AssetBytes.png(2, 2), "image/jpeg", 400, "image/png"),
                new Bad("JSON sent as model/gltf-binary", "{\"asset\":{\"version\":\"2.0\"}}".getBytes(),
                        "model/gltf-binary", 400, "JSON"),
                new Bad("a glb sent as model/obj", Arrays.copyOf(glb, glb.length - 4), "model/obj", 400, "glb"),
                new Bad("JSON without asset.version", "{\"asset\":{}}".getBytes(), "model/gltf+json", 400,
                        "asset.version"),
                new Bad("an empty body", new byte[0], "model/obj", 400, "empty"),
                new Bad("an unsupported media type", "v 0 0 0 # text\n".getBytes(), "text/plain", 415, "model/obj"),
                new Bad("no media type at all", AssetBytes.png(5, 7), null, 415, "missing"));
        for (Bad bad : bads) {
            var request = post("/api/assets").content(bad.bytes());
            if (bad.mediaType() != null) {
                request.contentType(bad.mediaType());
            }
            mvc.perform(request)
                    .andExpect(status().is(bad.status()))
                    .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                    .andExpect(jsonPath("$.status").value(bad.status()))
                    .andExpect(jsonPath("$.detail").value(containsString(bad.detail())));
            mvc.perform(head("/api/assets/" + AssetIds.of(bad.bytes()))).andExpect(status().isNotFound());
        }
        mvc.perform(get("/actuator/health")).andExpect(status().isOk());
        upload(AssetBytes.fan(1000), "model/obj", 201); // at the limit
        upload(AssetBytes.gltfOf(1000), "model/gltf+json", 201);
    }

    @SuppressWarnings("unchecked")
    private static String scene(Map<String, Object> mesh) throws Exception {
        Map<String, Object> scene = new LinkedHashMap<>();
        scene.put("image", Map.of("width", 32, "height", 24, "format", "png"));
        scene.put("render", Map.of("samples", 1));
        scene.put("camera", Map.of("position", List.of(2, 2, 3), "lookAt", List.of(0.3, 0.3, 0.3)));
        scene.put("objects", List.of(mesh));
        return JSON.writeValueAsString(scene);
    }

    private byte[] render(Map<String, Object> mesh) throws Exception {
        return AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON).content(scene(mesh)))
                .andExpect(status().isOk())
                .andReturn().getResponse().getContentAsByteArray();
    }

    @Test
    void aSceneNamingAMeshAssetRendersAsTheSameMeshInline() throws Exception {
        String text = AssetBytes.TETRAHEDRON + "# rendered by asset and inline\n";
        byte[] obj = text.getBytes(StandardCharsets.UTF_8);
        upload(obj, "model/obj", 201);
        byte[] byAsset = render(Map.of("type", "mesh", "asset", AssetIds.of(obj), "scale", 1.5));
        byte[] inline = render(Map.of("type", "mesh", "obj", text, "scale", 1.5));
        assertThat(byAsset).isEqualTo(inline);
    }

    @Test
    void aSceneNamingAMissingAssetIsA400NamingTheFieldAndTheId() throws Exception {
        String missing = "sha256-" + "ab".repeat(32);
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON)
                        .content(scene(Map.of("type", "mesh", "asset", missing))))
                .andExpect(status().isBadRequest())
                .andExpect(content().contentType(MediaType.APPLICATION_PROBLEM_JSON))
                .andExpect(jsonPath("$.errors[0].field").value("objects[0].asset"))
                .andExpect(jsonPath("$.errors[0].message").value(containsString(missing)));
    }

    @Test
    void aSceneNamingAnImageAssetAsAMeshIsA400() throws Exception {
        byte[] png = AssetBytes.png(8, 8);
        upload(png, "image/png", 201);
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON)
                        .content(scene(Map.of("type", "mesh", "asset", AssetIds.of(png)))))
                .andExpect(status().isBadRequest())
                .andExpect(jsonPath("$.errors[0].field").value("objects[0].asset"))
                .andExpect(jsonPath("$.errors[0].message").value(containsString("image/png")));
    }

    @Test
    void aMalformedAssetIdInASceneIsA400() throws Exception {
        AsyncMvc.perform(mvc, post("/api/render").contentType(MediaType.APPLICATION_JSON)
                        .content(scene(Map.of("type", "mesh", "asset", "sha256-XYZ"))))
                .andExpect(status().isBadRequest())
                .andExpect(jsonPath("$.errors[0].field").value("objects[0].asset"));
    }
}

package studio.server.scene.format;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import tools.jackson.databind.SerializationFeature;
import tools.jackson.databind.json.JsonMapper;

/**
 * The published scene schema: its shape, and that the copy the editor is checked against
 * (frontend/src/model/scene.schema.json) is exactly what the server publishes. After a deliberate
 * change to the format, rewrite the copy with -Dstudio.updateSchema=true.
 */
class SceneSchemaTest {

    static final Path EDITOR_COPY = Path.of("../../frontend/src/model/scene.schema.json");

    static String published() {
        return JsonMapper.builder().enable(SerializationFeature.INDENT_OUTPUT).build()
                .writeValueAsString(SceneSchema.of(SceneLimits.DEFAULTS)) + "\n";
    }

    @Test
    void editorCopyIsWhatTheServerPublishes() throws IOException {
        String schema = published();
        if (Boolean.getBoolean("studio.updateSchema")) {
            Files.writeString(EDITOR_COPY, schema, StandardCharsets.UTF_8);
        }
        assertTrue(Files.exists(EDITOR_COPY), "missing " + EDITOR_COPY.toAbsolutePath());
        assertEquals(schema, Files.readString(EDITOR_COPY, StandardCharsets.UTF_8),
                "the editor's scene.schema.json is out of date: run the server tests with -Dstudio.updateSchema=true");
    }

    @Test
    @SuppressWarnings("unchecked")
    void objectsMaterialsAndLightsAreDiscriminatedByType() {
        Map<String, Object> defs = (Map<String, Object>) SceneSchema.of(SceneLimits.DEFAULTS).get("$defs");
        assertEquals(List.of(Map.of("$ref", "#/$defs/SphereObject"), Map.of("$ref", "#/$defs/BoxObject"),
                Map.of("$ref", "#/$defs/PlaneObject"), Map.of("$ref", "#/$defs/MeshObject"),
                Map.of("$ref", "#/$defs/GltfObject")),
                ((Map<String, Object>) defs.get("Object")).get("oneOf"));
        assertEquals(6, ((List<?>) ((Map<String, Object>) defs.get("Material")).get("oneOf")).size());
        Map<String, Object> glass = (Map<String, Object>) defs.get("GlassMaterial");
        Map<String, Object> properties = (Map<String, Object>) glass.get("properties");
        assertEquals(Map.of("const", "glass"), properties.get("type"));
        assertEquals(List.of("type", "color", "ior", "specular", "shininess", "texture"),
                List.copyOf(properties.keySet()));
        assertEquals(false, glass.get("additionalProperties"));
        assertEquals(List.of(Map.of("$ref", "#/$defs/CheckerTexture"), Map.of("$ref", "#/$defs/ImageTexture")),
                ((Map<String, Object>) defs.get("Texture")).get("oneOf"));
    }

    @Test
    @SuppressWarnings("unchecked")
    void limitsAndRulesBecomeBounds() {
        SceneLimits limits = new SceneLimits(640, 480, 64, 4, 50, 3, 5000, 1024);
        Map<String, Object> schema = SceneSchema.of(limits);
        Map<String, Object> defs = (Map<String, Object>) schema.get("$defs");
        Map<String, Object> image = (Map<String, Object>) ((Map<String, Object>) defs.get("Image")).get("properties");
        assertEquals(Map.of("type", "integer", "minimum", 1, "maximum", 640, "default", 800), image.get("width"));
        Map<String, Object> root = (Map<String, Object>) schema.get("properties");
        assertEquals(50, ((Map<String, Object>) root.get("objects")).get("maxItems"));
        assertEquals(List.of("objects"), schema.get("required"));
        Map<String, Object> sphere = (Map<String, Object>) ((Map<String, Object>) defs.get("SphereObject"))
                .get("properties");
        assertEquals(Map.of("type", "number", "exclusiveMinimum", 0, "default", 1.0), sphere.get("radius"));
        Map<String, Object> center = (Map<String, Object>) sphere.get("center");
        assertEquals(3, center.get("minItems"));
        assertEquals(3, center.get("maxItems"));
        Map<String, Object> camera = (Map<String, Object>) ((Map<String, Object>) defs.get("Camera")).get("properties");
        assertEquals(Map.of("type", "number", "exclusiveMinimum", 0, "exclusiveMaximum", 180, "default", 50.0), camera.get("fov"));
        Map<String, Object> background = (Map<String, Object>) root.get("background");
        assertEquals("^(#[0-9a-fA-F]{6})$", background.get("pattern"));
    }

    @Test
    @SuppressWarnings("unchecked")
    void publishesEachFieldsDefaultAsTheMapperFillsItIn() {
        Map<String, Object> schema = SceneSchema.of(SceneLimits.DEFAULTS);
        Map<String, Object> defs = (Map<String, Object>) schema.get("$defs");
        Map<String, Object> root = (Map<String, Object>) schema.get("properties");
        assertEquals(SceneDefaults.NAME, ((Map<String, Object>) root.get("name")).get("default"));
        Map<String, Object> render = (Map<String, Object>) ((Map<String, Object>) defs.get("Render")).get("properties");
        assertEquals(SceneDefaults.SAMPLER, ((Map<String, Object>) render.get("sampler")).get("default"));
        // render.adaptive's default depends on the sampler: none is published
        assertEquals(null, ((Map<String, Object>) render.get("adaptive")).get("default"));
        Map<String, Object> mirror = (Map<String, Object>) ((Map<String, Object>) defs.get("MirrorMaterial")).get("properties");
        assertEquals("#ffffff", ((Map<String, Object>) mirror.get("color")).get("default"));
        assertEquals(1.0, ((Map<String, Object>) mirror.get("reflectivity")).get("default"));
        Map<String, Object> chalk = (Map<String, Object>) ((Map<String, Object>) defs.get("ChalkMaterial")).get("properties");
        assertEquals("#cccccc", ((Map<String, Object>) chalk.get("color")).get("default"));
        Map<String, Object> light = (Map<String, Object>) ((Map<String, Object>) defs.get("PointLight")).get("properties");
        assertEquals(false, ((Map<String, Object>) light.get("falloff")).get("default"));
        // a required field has none
        assertEquals(null, ((Map<String, Object>) root.get("objects")).get("default"));
    }
}

package studio.server.scene.format;

import java.util.Map;

import org.springframework.http.MediaType;
import org.springframework.http.ResponseEntity;
import org.springframework.web.bind.annotation.GetMapping;
import org.springframework.web.bind.annotation.RestController;

/** GET /api/scene-schema: the scene format as JSON Schema, with this server's limits. */
@RestController
class SceneSchemaController {

    private final Map<String, Object> schema;

    SceneSchemaController(SceneLimits limits) {
        this.schema = SceneSchema.of(limits);
    }

    @GetMapping(path = "/api/scene-schema", produces = {"application/schema+json", MediaType.APPLICATION_JSON_VALUE})
    ResponseEntity<Map<String, Object>> schema() {
        return ResponseEntity.ok(schema);
    }
}

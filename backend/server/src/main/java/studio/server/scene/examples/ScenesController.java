package studio.server.scene.examples;

import java.util.List;

import org.springframework.http.HttpStatus;
import org.springframework.http.MediaType;
import org.springframework.http.ResponseEntity;
import org.springframework.web.bind.annotation.GetMapping;
import org.springframework.web.bind.annotation.PathVariable;
import org.springframework.web.bind.annotation.RestController;
import org.springframework.web.server.ResponseStatusException;

import studio.server.scene.format.SceneNames;

/** GET /api/scenes and /api/scenes/{name}: the example scenes. */
@RestController
class ScenesController {

    /** One entry of the example list. */
    record SceneSummary(String name) {
    }

    private final ExampleScenes examples = ExampleScenes.fromClasspath();

    @GetMapping("/api/scenes")
    List<SceneSummary> list() {
        return examples.names().stream().map(SceneSummary::new).toList();
    }

    @GetMapping("/api/scenes/{name}")
    ResponseEntity<byte[]> get(@PathVariable String name) {
        byte[] json = examples.get(name).orElseThrow(() ->
                new ResponseStatusException(HttpStatus.NOT_FOUND, "no example scene named '" + SceneNames.toFileStem(name) + "'"));
        return ResponseEntity.ok().contentType(MediaType.APPLICATION_JSON).body(json);
    }
}

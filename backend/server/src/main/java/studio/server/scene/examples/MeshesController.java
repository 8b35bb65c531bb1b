package studio.server.scene.examples;

import org.springframework.http.HttpStatus;
import org.springframework.http.MediaType;
import org.springframework.http.ResponseEntity;
import org.springframework.web.bind.annotation.GetMapping;
import org.springframework.web.bind.annotation.RequestParam;
import org.springframework.web.bind.annotation.RestController;
import org.springframework.web.server.ResponseStatusException;

import studio.server.scene.compiling.MeshFiles;

/**
 * GET /api/meshes?file=meshes/NAME.obj: a mesh shipped with the example scenes, as OBJ text, so
 * the editor can show what an example's {@code "file"} names.
 */
@RestController
class MeshesController {

    private final MeshFiles bundled = MeshFiles.bundled();

    @GetMapping("/api/meshes")
    ResponseEntity<String> get(@RequestParam String file) {
        String obj;
        try {
            obj = bundled.read(file);
        } catch (IllegalArgumentException e) {
            throw new ResponseStatusException(HttpStatus.NOT_FOUND, e.getMessage());
        }
        return ResponseEntity.ok().contentType(new MediaType("text", "plain", java.nio.charset.StandardCharsets.UTF_8))
                .body(obj);
    }
}

package studio.server.scene.gltf;

import java.util.List;

/**
 * A glTF model read for rendering: its parts, in the model's own space (the node transforms
 * applied), and what it holds that is not drawn.
 *
 * @param warnings one sentence for each thing in the file that is not drawn or not drawn as it says
 *                 (skins, animations, cameras, lights, unknown extensions, non-triangle primitives...)
 */
public record GltfModel(List<GltfPart> parts, List<String> warnings) {

    public GltfModel {
        parts = List.copyOf(parts);
        warnings = List.copyOf(warnings);
    }

    public int triangleCount() {
        return parts.stream().mapToInt(p -> p.mesh().triangleCount()).sum();
    }
}

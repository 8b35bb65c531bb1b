package studio.server.scene.gltf;

import studio.engine.material.Material;
import studio.engine.mesh.MeshData;

/**
 * The triangles of a model that share one material (every instance of every primitive with it,
 * placed by its node's transform), as one engine mesh.
 *
 * @param uvs     TEXCOORD_0, two per vertex, or null: (u, 1 - v), since glTF's v runs down the image and the
 *                engine's (as OBJ's vt) up
 * @param texture the base colour texture, or null
 */
public record GltfPart(MeshData mesh, double[] uvs, Material material, GltfTexture texture) {
}

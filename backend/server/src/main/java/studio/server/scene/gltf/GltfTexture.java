package studio.server.scene.gltf;

/**
 * A material's base colour texture: the image's bytes (PNG or JPEG, not yet decoded) and where they
 * came from, to name it in a message. Its colour multiplies the material's base colour factor.
 */
public record GltfTexture(byte[] image, String mediaType, String source) {
}

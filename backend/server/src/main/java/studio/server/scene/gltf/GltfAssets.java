package studio.server.scene.gltf;

/**
 * Where a .gltf's buffers and images named by asset id ({@code "uri": "sha256-..."}) are read from:
 * the asset store, on the service. Nothing else outside the file is ever read.
 */
@FunctionalInterface
public interface GltfAssets {

    /** The bytes of the asset {@code id} (a valid id), or null if there is no such asset. */
    byte[] bytes(String id);

    /** No assets: a .gltf must embed its buffers and images (the command line, tests). */
    static GltfAssets none() {
        return id -> null;
    }
}

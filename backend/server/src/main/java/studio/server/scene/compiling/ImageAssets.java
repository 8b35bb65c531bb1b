package studio.server.scene.compiling;

/**
 * Where an image texture's {@code asset} is read from: the bytes stored on this server (or its
 * cluster) by POST /api/assets, as {@link MeshAssets} for meshes. The command line has none: it reads
 * {@code file}s beside the scene.
 */
@FunctionalInterface
public interface ImageAssets {

    /**
     * The PNG or JPEG bytes of the asset {@code id} (a valid id), or null if this server has no such asset.
     *
     * @throws IllegalArgumentException saying why the asset cannot be an image (it is a mesh, ...)
     */
    byte[] image(String id);

    /** No assets at all (the command line, tests). */
    static ImageAssets none() {
        return id -> {
            throw new IllegalArgumentException("assets cannot be read here; name the image file beside the scene in "
                    + "\"file\"");
        };
    }
}

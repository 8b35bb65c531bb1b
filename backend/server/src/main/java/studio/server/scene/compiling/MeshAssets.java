package studio.server.scene.compiling;

/**
 * Where a mesh's or a glTF model's {@code asset} is read from: the bytes stored on this server (or
 * its cluster) by POST /api/assets, which the asset feature offers the compiler. The command line has
 * none: it reads {@code file}s beside the scene.
 */
@FunctionalInterface
public interface MeshAssets {

    /**
     * The OBJ bytes of the asset {@code id} (a valid id), or null if this server has no such asset.
     *
     * @throws IllegalArgumentException saying why the asset cannot be a mesh (it is an image, ...)
     */
    byte[] obj(String id);

    /**
     * The bytes of the glTF model (.glb or .gltf) {@code id}, or null if this server has no such asset.
     *
     * @throws IllegalArgumentException saying why the asset cannot be a glTF model
     */
    default byte[] gltf(String id) {
        throw new IllegalArgumentException(NONE);
    }

    /** The bytes of any asset (a .gltf's buffer or image named by id), or null if there is none. */
    default byte[] bytes(String id) {
        return null;
    }

    String NONE = "assets cannot be read here; name the model's file beside the scene in \"file\"";

    /** No assets at all (the command line, tests). */
    static MeshAssets none() {
        return id -> {
            throw new IllegalArgumentException("assets cannot be read here; name the OBJ file beside the scene in "
                    + "\"file\", or send the OBJ text inline as \"obj\"");
        };
    }
}

package studio.server.asset;

import studio.server.scene.compiling.ImageAssets;
import studio.server.scene.compiling.MeshAssets;

/** Where assets are kept, by id: this member's memory, backed by the cluster's copy in a cluster ({@link LocalAssets}). */
public interface AssetStore {

    /**
     * Keeps the asset unless it is kept already (then it only counts as used).
     *
     * @return true if it was not kept before
     * @throws AssetRefusedException (503 with Retry-After) if there is no room for it now
     */
    boolean put(Asset asset);

    /** The asset, counted as used; null if none is kept by that id. */
    Asset get(String id);

    /** Whether an asset is kept by that id on this member (without counting it as used). */
    boolean contains(String id);

    /**
     * The store as the scene compiler reads meshes' and models' assets: OBJ bytes for a mesh, glTF
     * bytes for a model, any bytes for a .gltf's buffer or image; null if none is kept by that id.
     */
    default MeshAssets meshes() {
        return new MeshAssets() {
            @Override
            public byte[] obj(String id) {
                return of(id, AssetType.OBJ, AssetType.OBJ, "a model/obj mesh");
            }

            @Override
            public byte[] gltf(String id) {
                return of(id, AssetType.GLB, AssetType.GLTF, "a glTF model (model/gltf-binary or model/gltf+json)");
            }

            @Override
            public byte[] bytes(String id) {
                Asset asset = get(id);
                return asset != null ? asset.bytes() : null;
            }

            private byte[] of(String id, AssetType one, AssetType other, String what) {
                Asset asset = get(id);
                if (asset != null && asset.type() != one && asset.type() != other) {
                    throw new IllegalArgumentException("the asset " + id + " is " + asset.type().mediaType()
                            + ", not " + what);
                }
                return asset != null ? asset.bytes() : null;
            }
        };
    }

    /** The store as the scene compiler reads textures' assets: PNG or JPEG bytes, or null if none is kept by that id. */
    default ImageAssets images() {
        return id -> {
            Asset asset = get(id);
            if (asset != null && asset.type() != AssetType.PNG && asset.type() != AssetType.JPEG) {
                throw new IllegalArgumentException("the asset " + id + " is " + asset.type().mediaType()
                        + ", not a PNG or JPEG image");
            }
            return asset != null ? asset.bytes() : null;
        };
    }
}

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

    /** The store as the scene compiler reads meshes' assets: OBJ bytes, or null if none is kept by that id. */
    default MeshAssets meshes() {
        return id -> {
            Asset asset = get(id);
            if (asset != null && asset.type() != AssetType.OBJ) {
                throw new IllegalArgumentException("the asset " + id + " is " + asset.type().mediaType()
                        + ", not a model/obj mesh");
            }
            return asset != null ? asset.bytes() : null;
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

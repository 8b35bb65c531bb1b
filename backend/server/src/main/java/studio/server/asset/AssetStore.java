package studio.server.asset;

/** Where assets are kept, by id: this member's memory ({@link LocalAssets}). */
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

    /** Whether an asset is kept by that id (without counting it as used). */
    boolean contains(String id);
}

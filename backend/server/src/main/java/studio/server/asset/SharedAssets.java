package studio.server.asset;

/**
 * The cluster's copy of the assets, which every member reads from when it lacks one (the cluster
 * feature offers it; without a cluster there is none). What it gives back is checked against its id
 * before use ({@link LocalAssets}), whatever its transport checked already.
 */
public interface SharedAssets {

    /** Puts the asset into the cluster's copy (a slow peer must not hold any lock of the caller's). */
    void share(Asset asset);

    /** The asset as the cluster holds it under {@code id}, or null. */
    Asset find(String id);

    /** No cluster. */
    SharedAssets NONE = new SharedAssets() {
        @Override
        public void share(Asset asset) {
        }

        @Override
        public Asset find(String id) {
            return null;
        }
    };
}

package studio.server.asset;

/**
 * The asset feature's limits, as configured and fitted to the memory budget.
 *
 * @param maxBytes      the largest asset, at most {@code storeBytes}
 * @param storeBytes    all assets kept at once: studio.assets.max-store-bytes, at most a quarter of the memory budget
 */
record AssetLimits(long maxBytes, long storeBytes) {

    static AssetLimits of(long maxBytes, long maxStoreBytes, long memoryBudget) {
        long store = Math.min(maxStoreBytes, memoryBudget / 4);
        return new AssetLimits(Math.min(maxBytes, store), store);
    }
}

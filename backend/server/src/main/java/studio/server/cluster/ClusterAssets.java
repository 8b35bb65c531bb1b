package studio.server.cluster;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;

import studio.server.asset.Asset;
import studio.server.asset.AssetType;
import studio.server.asset.SharedAssets;

/**
 * The cluster's copy of the assets: a sealed map by asset id ({@link ClusterMaps#ASSETS}), which
 * every member's asset store puts its uploads into and reads what it lacks from (checking the
 * bytes' SHA-256 against the id). Bounded per member by Hazelcast's LRU eviction
 * ({@link MemberConfig#withAssets}).
 */
final class ClusterAssets implements SharedAssets {

    /** An asset as the map holds it: its media type, then its bytes. */
    static final Codec<Asset> CODEC = new Codec<>() {
        @Override
        public void write(DataOutputStream out, Asset asset) throws IOException {
            out.writeUTF(asset.type().mediaType());
            out.write(asset.bytes());
        }

        @Override
        public Asset read(DataInputStream in) throws IOException {
            AssetType type = AssetType.ofMediaType(in.readUTF());
            if (type == null) {
                throw new IOException("not an asset's media type");
            }
            return Asset.of(type, in.readAllBytes());
        }
    };

    private final SealedMap<String, Asset> map;

    ClusterAssets(SealedMap<String, Asset> map) {
        this.map = map;
    }

    @Override
    public void share(Asset asset) {
        map.set(asset.id(), asset);
    }

    @Override
    public Asset find(String id) {
        return map.get(id);
    }
}

package studio.server.cluster;

import com.hazelcast.core.HazelcastInstance;

import studio.server.asset.Asset;

/**
 * This member's view of the cluster's data: every map, the tile queue and the event logs, sealed
 * with the cluster's secret ({@link Seal}); the one place that names each structure's codec and key
 * family (the family also tags {@code studio.cluster.rejected}).
 */
final class ClusterData {

    private final HazelcastInstance member;
    private final Seal seal;

    ClusterData(HazelcastInstance member, Seal seal) {
        this.member = member;
        this.seal = seal;
    }

    HazelcastInstance member() {
        return member;
    }

    Seal seal() {
        return seal;
    }

    SealedMap<String, JobRecord> jobs() {
        return new SealedMap<>(member.getMap(ClusterMaps.JOBS), ClusterMaps.JOBS, ClusterCodecs.JOB_RECORD, seal);
    }

    SealedMap<String, byte[]> scenes() {
        return new SealedMap<>(member.getMap(ClusterMaps.SCENES), ClusterMaps.SCENES, Codec.BYTES, seal);
    }

    SealedMap<String, Asset> assets() {
        return new SealedMap<>(member.getMap(ClusterMaps.ASSETS), ClusterMaps.ASSETS, ClusterAssets.CODEC, seal);
    }

    SealedMap<String, byte[]> images() {
        return new SealedMap<>(member.getMap(ClusterMaps.IMAGES), ClusterMaps.IMAGES, Codec.BYTES, seal);
    }

    SealedMap<String, String> cancels() {
        return new SealedMap<>(member.getMap(ClusterMaps.CANCELS), ClusterMaps.CANCELS, Codec.STRING, seal);
    }

    SealedMap<String, Long> seen() {
        return new SealedMap<>(member.getMap(ClusterMaps.SEEN), ClusterMaps.SEEN, Codec.LONG, seal);
    }

    SealedMap<Integer, TileResult> tiles(String jobId) {
        return new SealedMap<>(member.getMap(ClusterMaps.tiles(jobId)), ClusterMaps.TILES_FAMILY,
                ClusterCodecs.TILE_RESULT, seal);
    }

    SealedMap<Integer, TileClaim> claims(String jobId) {
        return new SealedMap<>(member.getMap(ClusterMaps.claims(jobId)), ClusterMaps.CLAIMS_FAMILY,
                ClusterCodecs.TILE_CLAIM, seal);
    }

    SealedQueue<TileTask> queue() {
        return new SealedQueue<>(member.getQueue(ClusterMaps.TILE_QUEUE), ClusterMaps.TILE_QUEUE,
                ClusterCodecs.TILE_TASK, seal);
    }

    EventLog events(String jobId) {
        return new EventLog(member.getRingbuffer(ClusterMaps.events(jobId)), seal);
    }
}

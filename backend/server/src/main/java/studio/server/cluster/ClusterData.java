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
    /** Before every structure's name: empty for the cluster's own structures. */
    private final String prefix;

    ClusterData(HazelcastInstance member, Seal seal) {
        this(member, seal, "");
    }

    private ClusterData(HazelcastInstance member, Seal seal, String prefix) {
        this.member = member;
        this.seal = seal;
        this.prefix = prefix;
    }

    /**
     * The same structures under names of their own, {@code prefix} before each: another member's
     * workers never read them, and a value sealed for one opens in no structure of the cluster's own
     * (the name is the seal's associated data). A job's tile, claim and event structures take the prefix
     * after their own family's name, so they match the family's configuration ({@link MemberConfig}: the
     * tile maps' time to live, the logs' capacity) and run the code a job's do. The start-up warm-up's
     * ({@link ClusterWarmUp}).
     */
    ClusterData named(String prefix) {
        return new ClusterData(member, seal, this.prefix + prefix);
    }

    HazelcastInstance member() {
        return member;
    }

    Seal seal() {
        return seal;
    }

    SealedMap<String, JobRecord> jobs() {
        return new SealedMap<>(member.getMap(prefix + ClusterMaps.JOBS), ClusterMaps.JOBS, ClusterCodecs.JOB_RECORD, seal);
    }

    SealedMap<String, byte[]> scenes() {
        return new SealedMap<>(member.getMap(prefix + ClusterMaps.SCENES), ClusterMaps.SCENES, Codec.BYTES, seal);
    }

    SealedMap<String, Asset> assets() {
        return new SealedMap<>(member.getMap(prefix + ClusterMaps.ASSETS), ClusterMaps.ASSETS, ClusterAssets.CODEC, seal);
    }

    SealedMap<String, byte[]> images() {
        return new SealedMap<>(member.getMap(prefix + ClusterMaps.IMAGES), ClusterMaps.IMAGES, Codec.BYTES, seal);
    }

    SealedMap<String, String> cancels() {
        return new SealedMap<>(member.getMap(prefix + ClusterMaps.CANCELS), ClusterMaps.CANCELS, Codec.STRING, seal);
    }

    SealedMap<String, Long> seen() {
        return new SealedMap<>(member.getMap(prefix + ClusterMaps.SEEN), ClusterMaps.SEEN, Codec.LONG, seal);
    }

    SealedMap<Integer, TileResult> tiles(String jobId) {
        return new SealedMap<>(member.getMap(ClusterMaps.tiles(prefix + jobId)), ClusterMaps.TILES_FAMILY,
                ClusterCodecs.TILE_RESULT, seal);
    }

    SealedMap<Integer, TileClaim> claims(String jobId) {
        return new SealedMap<>(member.getMap(ClusterMaps.claims(prefix + jobId)), ClusterMaps.CLAIMS_FAMILY,
                ClusterCodecs.TILE_CLAIM, seal);
    }

    SealedQueue<TileTask> queue() {
        return new SealedQueue<>(member.getQueue(prefix + ClusterMaps.TILE_QUEUE), ClusterMaps.TILE_QUEUE,
                ClusterCodecs.TILE_TASK, seal);
    }

    EventLog events(String jobId) {
        return new EventLog(member.getRingbuffer(ClusterMaps.events(prefix + jobId)), seal);
    }
}

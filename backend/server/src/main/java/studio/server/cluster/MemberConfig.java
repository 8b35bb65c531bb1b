package studio.server.cluster;

import com.hazelcast.config.Config;
import com.hazelcast.config.JoinConfig;
import com.hazelcast.config.MapConfig;
import com.hazelcast.config.NetworkConfig;
import com.hazelcast.config.QueueConfig;
import com.hazelcast.config.RingbufferConfig;

/**
 * The Hazelcast configuration of this service's member: join only the listed members over TCP, or
 * on Kubernetes the pods behind the configured headless service (multicast, auto-detection and
 * Hazelcast's phone-home stay off, so a member writes to no address it was not given), listen on the configured port only (no auto-increment: a second member on a
 * machine must be given its own port), and leave the member's shutdown to the application, which
 * drains its renders first. Every map, the tile queue and the event logs keep one backup on another
 * member, so the loss of any one member loses no job, tile or image.
 */
public final class MemberConfig {

    /** Backups of every structure: one member may die at a time without loss. */
    static final int BACKUPS = 1;
    /**
     * A job's event log holds its status changes and one event per tile: a 4096x4096 image has
     * 16,384 tiles of 32x32.
     */
    static final int EVENTS_CAPACITY = 16_384 + 1_024;
    /**
     * A job's tile results and claims are destroyed when its render ends; a worker that finishes a
     * tile after that creates the map again, which this removes.
     */
    static final int TILE_MAPS_TTL_SECONDS = 3_600;

    private MemberConfig() {
    }

    public static Config of(ClusterProperties cluster) {
        Config config = new Config();
        config.setClusterName(cluster.name());
        config.setProperty("hazelcast.phone.home.enabled", "false");
        config.setProperty("hazelcast.logging.type", "slf4j");
        // on SIGTERM Spring drains the renders, then shuts the member down (gracefully: its partitions
        // migrate first); Hazelcast's own hook would take the member away before the drain
        config.setProperty("hazelcast.shutdownhook.enabled", "false");
        NetworkConfig network = config.getNetworkConfig();
        network.setPort(cluster.port()).setPortAutoIncrement(false);
        if (!cluster.bindAddress().isEmpty()) {
            network.getInterfaces().setEnabled(true).addInterface(cluster.bindAddress());
            config.setProperty("hazelcast.socket.bind.any", "false");
        }
        JoinConfig join = network.getJoin();
        join.getMulticastConfig().setEnabled(false);
        join.getAutoDetectionConfig().setEnabled(false);
        if (cluster.onKubernetes()) {
            // DNS lookup mode: the headless service's A records are the members; no API access needed
            join.getKubernetesConfig().setEnabled(true).setProperty("service-dns", cluster.kubernetesServiceDns())
                    .setProperty("service-port", Integer.toString(cluster.port()));
        } else {
            join.getTcpIpConfig().setEnabled(true).setMembers(cluster.members());
        }
        for (String map : new String[] {ClusterMaps.JOBS, ClusterMaps.SCENES, ClusterMaps.IMAGES, ClusterMaps.CANCELS,
                ClusterMaps.SEEN}) {
            config.addMapConfig(new MapConfig(map).setBackupCount(BACKUPS));
        }
        config.addMapConfig(new MapConfig(ClusterMaps.tilesPattern()).setBackupCount(BACKUPS)
                .setTimeToLiveSeconds(TILE_MAPS_TTL_SECONDS));
        config.addMapConfig(new MapConfig(ClusterMaps.claimsPattern()).setBackupCount(BACKUPS)
                .setTimeToLiveSeconds(TILE_MAPS_TTL_SECONDS));
        config.addQueueConfig(new QueueConfig(ClusterMaps.TILE_QUEUE).setBackupCount(BACKUPS));
        config.addRingBufferConfig(new RingbufferConfig(ClusterMaps.eventsPattern()).setBackupCount(BACKUPS)
                .setCapacity(EVENTS_CAPACITY));
        return config;
    }
}

package studio.server.cluster;

import com.hazelcast.config.AdvancedNetworkConfig;
import com.hazelcast.config.ClassFilter;
import com.hazelcast.config.Config;
import com.hazelcast.config.InterfacesConfig;
import com.hazelcast.config.JavaSerializationFilterConfig;
import com.hazelcast.config.JoinConfig;
import com.hazelcast.config.EvictionConfig;
import com.hazelcast.config.EvictionPolicy;
import com.hazelcast.config.MapConfig;
import com.hazelcast.config.MaxSizePolicy;
import com.hazelcast.config.QueueConfig;
import com.hazelcast.config.RingbufferConfig;
import com.hazelcast.config.ServerSocketEndpointConfig;

/**
 * The Hazelcast configuration of this service's member. The member's socket accepts members only
 * (an advanced network with a member endpoint and no client endpoint: a Hazelcast client cannot
 * connect), on the configured address and port (no auto-increment: a second member on a machine
 * must be given its own port); the cluster's name carries a tag of the secret, so a member of
 * another secret never joins ({@link ClusterSecret}); Java serialization refuses every class but
 * the exceptions members send each other (all the cluster holds is sealed bytes under String and
 * Integer keys). It joins only the listed
 * members over TCP, or on Kubernetes the pods behind the configured headless service (multicast,
 * auto-detection and Hazelcast's phone-home stay off, so a member writes to no address it was not
 * given), and leaves its shutdown to the application, which hands its jobs over or drains its
 * renders first. Every map, the tile queue and the event logs keep one backup on another member,
 * so the loss of any one member loses no job, tile or image.
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
    /**
     * What Java serialization may read: only Hazelcast's own classes and the JDK classes an exception
     * is made of. Members send each other exceptions (a partition migrating, a member gone) by Java
     * serialization, and retry on them; refusing those too broke every operation while partitions
     * moved. Every other class (java.util.Date, the application's, an outsider's) is refused:
     * Hazelcast's defaults, which allow all of java.*, are off.
     */
    static final String[] JAVA_SERIALIZATION_PREFIXES = {"com.hazelcast."};
    static final String[] JAVA_SERIALIZATION_CLASSES = {"java.lang.Throwable", "java.lang.Exception",
            "java.lang.RuntimeException", "java.lang.IllegalStateException", "java.lang.IllegalArgumentException",
            "java.lang.UnsupportedOperationException", "java.lang.NullPointerException", "java.lang.StackTraceElement",
            "[Ljava.lang.StackTraceElement;", "[Ljava.lang.Throwable;", "java.util.Collections$EmptyList",
            "java.util.Collections$UnmodifiableList", "java.util.Collections$UnmodifiableRandomAccessList",
            "java.util.Collections$UnmodifiableCollection", "java.util.ArrayList",
            "java.util.concurrent.CancellationException", "java.util.concurrent.TimeoutException",
            "java.util.concurrent.ExecutionException"};

    private MemberConfig() {
    }

    static Config of(ClusterProperties cluster, ClusterSecret secret) {
        Config config = new Config();
        config.setClusterName(secret.clusterName(cluster.name()));
        config.setProperty("hazelcast.phone.home.enabled", "false");
        config.setProperty("hazelcast.logging.type", "slf4j");
        // nothing reads Hazelcast's own metrics (the service's are Micrometer's): collecting them every 5 s and
        // publishing them to JMX showed in the members' CPU samples (docs/cluster.md, "Where two members' CPU goes")
        config.getMetricsConfig().setEnabled(false);
        // on SIGTERM the application hands its jobs over (or drains its renders), then shuts the member down
        // (gracefully: its partitions migrate first); Hazelcast's own hook would take the member away before that
        config.setProperty("hazelcast.shutdownhook.enabled", "false");
        config.getSerializationConfig().setJavaSerializationFilterConfig(new JavaSerializationFilterConfig()
                .setDefaultsDisabled(true).setWhitelist(new ClassFilter().addPrefixes(JAVA_SERIALIZATION_PREFIXES)
                        .addClasses(JAVA_SERIALIZATION_CLASSES)));
        AdvancedNetworkConfig network = config.getAdvancedNetworkConfig().setEnabled(true);
        ServerSocketEndpointConfig members = new ServerSocketEndpointConfig();
        members.setPort(cluster.port()).setPortAutoIncrement(false);
        if (!cluster.bindAddress().isEmpty()) {
            members.setInterfaces(new InterfacesConfig().setEnabled(true).addInterface(cluster.bindAddress()));
            config.setProperty("hazelcast.socket.bind.any", "false");
        }
        network.setMemberEndpointConfig(members);
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

    /** The configuration of a member of {@code cluster}, with its secret. */
    public static Config of(ClusterProperties cluster) {
        return of(cluster, ClusterSecret.of(cluster));
    }

    /**
     * The assets' map ({@link ClusterAssets}): one backup, and on each member at most
     * {@code maxBytesPerMember} of heap (Hazelcast's own measure of its entries, primaries and
     * backups), the least recently used entries evicted first.
     */
    static Config withAssets(Config config, long maxBytesPerMember) {
        int megabytes = (int) Math.max(1, Math.min(Integer.MAX_VALUE, maxBytesPerMember >> 20));
        config.addMapConfig(new MapConfig(ClusterMaps.ASSETS).setBackupCount(BACKUPS)
                .setEvictionConfig(new EvictionConfig().setEvictionPolicy(EvictionPolicy.LRU)
                        .setMaxSizePolicy(MaxSizePolicy.USED_HEAP_SIZE).setSize(megabytes)));
        return config;
    }
}

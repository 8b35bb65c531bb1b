package studio.server.cluster;

import com.hazelcast.config.Config;
import com.hazelcast.config.JoinConfig;
import com.hazelcast.config.NetworkConfig;

/**
 * The Hazelcast configuration of this service's member: join only the listed members over TCP
 * (multicast, auto-detection and Hazelcast's phone-home stay off, so a member writes to no address
 * it was not given), listen on the configured port only (no auto-increment: a second member on a
 * machine must be given its own port), and leave the member's shutdown to the application, which
 * drains its renders first.
 */
public final class MemberConfig {

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
        join.getTcpIpConfig().setEnabled(true).setMembers(cluster.members());
        return config;
    }
}

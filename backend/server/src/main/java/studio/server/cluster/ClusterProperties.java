package studio.server.cluster;

import java.util.List;

import org.springframework.boot.context.properties.ConfigurationProperties;
import org.springframework.boot.context.properties.bind.DefaultValue;

/**
 * The cluster this service is a member of (environment: STUDIO_CLUSTER_MEMBERS and so on).
 *
 * @param port        this member's cluster port
 * @param members     {@code host:port} of the members to join (this one may be among them); empty: a
 *                    cluster of one, which starts no Hazelcast member and touches no network
 * @param name        the cluster's name: members of other names never join this one
 * @param bindAddress the address the member listens on and gives the others (e.g. 127.0.0.1);
 *                    empty: Hazelcast picks one of the machine's addresses
 */
@ConfigurationProperties("studio.cluster")
public record ClusterProperties(@DefaultValue("5701") int port, @DefaultValue List<String> members,
                                @DefaultValue("ray-studio") String name, @DefaultValue("") String bindAddress) {

    public ClusterProperties {
        members = members == null ? List.of()
                : members.stream().map(String::trim).filter(member -> !member.isEmpty()).toList();
        if (port < 1 || port > 65535) {
            throw new IllegalArgumentException("studio.cluster.port must be a port number (1-65535): " + port);
        }
    }

    /** True when members are configured: only then does this service start a Hazelcast member. */
    public boolean clustered() {
        return !members.isEmpty();
    }
}

package studio.server.cluster;

import java.util.List;

import org.springframework.boot.context.properties.ConfigurationProperties;
import org.springframework.boot.context.properties.bind.ConstructorBinding;
import org.springframework.boot.context.properties.bind.DefaultValue;

/**
 * The cluster this service is a member of (environment: STUDIO_CLUSTER_MEMBERS and so on).
 *
 * @param port        this member's cluster port
 * @param members     host:port of the members to join (this one may be among them); empty: a
 *                    cluster of one, which starts no Hazelcast member and touches no network
 * @param name        the cluster's name: members of other names never join this one
 * @param bindAddress the address the member listens on and gives the others (e.g. 127.0.0.1);
 *                    empty: Hazelcast picks one of the machine's addresses
 * @param kubernetesServiceDns on Kubernetes, the DNS name of a headless service over the members'
 *                    pods (e.g. ray-studio-cluster.default.svc.cluster.local): the members find
 *                    each other through it (Hazelcast's Kubernetes discovery, DNS lookup mode, which needs
 *                    no access to the Kubernetes API) instead of a member list; empty: not on Kubernetes
 * @param secret      the secret every member holds (STUDIO_CLUSTER_SECRET, at least 32 bytes): only
 *                    members with it join, and everything in the cluster is sealed with it; a
 *                    clustered member without one refuses to start
 * @param insecure    true: a clustered member without a secret starts anyway, with a public demo
 *                    secret that protects nothing (a demo on one machine)
 */
@ConfigurationProperties("studio.cluster")
public record ClusterProperties(@DefaultValue("5701") int port, @DefaultValue List<String> members,
                                @DefaultValue("ray-studio") String name, @DefaultValue("") String bindAddress,
                                @DefaultValue("") String kubernetesServiceDns, @DefaultValue("") String secret,
                                @DefaultValue("false") boolean insecure) {

    @ConstructorBinding
    public ClusterProperties {
        members = members == null ? List.of()
                : members.stream().map(String::trim).filter(member -> !member.isEmpty()).toList();
        kubernetesServiceDns = kubernetesServiceDns == null ? "" : kubernetesServiceDns.trim();
        secret = secret == null ? "" : secret.trim();
        if (port < 1 || port > 65535) {
            throw new IllegalArgumentException("studio.cluster.port must be a port number (1-65535): " + port);
        }
        if (!members.isEmpty() && !kubernetesServiceDns.isEmpty()) {
            throw new IllegalArgumentException("set studio.cluster.members or studio.cluster.kubernetes-service-dns, "
                    + "not both: the members find each other one way");
        }
    }

    /** Members found by a list, not on Kubernetes, holding {@code secret}. */
    public ClusterProperties(int port, List<String> members, String name, String bindAddress, String secret) {
        this(port, members, name, bindAddress, "", secret, false);
    }

    /**
     * True when members are configured, or found on Kubernetes: only then does this service start a
     * Hazelcast member.
     */
    public boolean clustered() {
        return !members.isEmpty() || onKubernetes();
    }

    /** True when the members find each other through a Kubernetes headless service. */
    public boolean onKubernetes() {
        return !kubernetesServiceDns.isEmpty();
    }

    /** Never the secret. */
    @Override
    public String toString() {
        return "ClusterProperties[port=" + port + ", members=" + members + ", name=" + name + ", bindAddress="
                + bindAddress + ", kubernetesServiceDns=" + kubernetesServiceDns + ", secret=" + (secret.isEmpty() ? "none"
                : "(set)") + ", insecure=" + insecure + "]";
    }
}

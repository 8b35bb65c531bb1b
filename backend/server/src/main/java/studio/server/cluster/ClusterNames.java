package studio.server.cluster;

import com.hazelcast.cluster.Member;

/** How members are named in the API: {@code host:port}. */
public final class ClusterNames {

    private ClusterNames() {
    }

    public static String address(Member member) {
        return member.getAddress().getHost() + ":" + member.getAddress().getPort();
    }
}

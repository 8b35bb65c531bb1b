package studio.server.cluster;

import org.springframework.boot.health.contributor.Health;
import org.springframework.boot.health.contributor.HealthIndicator;

import com.hazelcast.core.HazelcastInstance;

/**
 * The cluster in GET /actuator/health/cluster: how many members it has and this member's address
 * (never the cluster's name, which carries a tag of its secret). Without configured members the service is a cluster of one that started no
 * Hazelcast member ({@code "member": "none"}).
 */
final class ClusterHealth implements HealthIndicator {

    /** Null in a cluster of one. */
    private final HazelcastInstance member;

    ClusterHealth(HazelcastInstance member) {
        this.member = member;
    }

    /** The members this one sees: 1 in a cluster of one, 0 once this member has shut down. */
    int members() {
        if (member == null) {
            return 1;
        }
        return member.getLifecycleService().isRunning() ? member.getCluster().getMembers().size() : 0;
    }

    @Override
    public Health health() {
        if (member == null) {
            return Health.up().withDetail("members", 1).withDetail("member", "none").build();
        }
        if (!member.getLifecycleService().isRunning()) {
            return Health.down().withDetail("members", 0).withDetail("reason", "the member has shut down").build();
        }
        return Health.up()
                .withDetail("members", member.getCluster().getMembers().size())
                .withDetail("member", ClusterNames.address(member.getCluster().getLocalMember()))
                .build();
    }
}

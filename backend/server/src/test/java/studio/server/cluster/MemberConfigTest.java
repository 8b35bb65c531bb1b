package studio.server.cluster;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.mockito.Mockito.mock;
import static org.mockito.Mockito.when;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.springframework.context.annotation.ConditionContext;
import org.springframework.mock.env.MockEnvironment;

import com.hazelcast.config.Config;
import com.hazelcast.config.JoinConfig;

/** How a member finds the others: a member list over TCP, or a Kubernetes headless service by DNS. */
class MemberConfigTest {

    @Test
    void aMemberListJoinsOverTcpOnly() {
        Config config = MemberConfig.of(new ClusterProperties(5701, List.of("a:5701", "b:5701"), "n", "",
                TestMember.SECRET));
        JoinConfig join = config.getAdvancedNetworkConfig().getJoin();
        assertThat(join.getTcpIpConfig().isEnabled()).isTrue();
        assertThat(join.getTcpIpConfig().getMembers()).containsExactly("a:5701", "b:5701");
        assertThat(join.getKubernetesConfig().isEnabled()).isFalse();
        assertThat(join.getMulticastConfig().isEnabled()).isFalse();
        assertThat(join.getAutoDetectionConfig().isEnabled()).isFalse();
        assertThat(config.getMetricsConfig().isEnabled()).as("Hazelcast's own metrics, read by no one").isFalse();
    }

    @Test
    void onKubernetesTheMembersAreTheHeadlessServicesRecords() {
        ClusterProperties cluster = new ClusterProperties(5701, List.of(), "n", "", " studio-cluster.ns.svc.cluster.local ",
                TestMember.SECRET, false);
        assertThat(cluster.clustered()).isTrue();
        Config config = MemberConfig.of(cluster);
        JoinConfig join = config.getAdvancedNetworkConfig().getJoin();
        assertThat(join.getKubernetesConfig().isEnabled()).isTrue();
        assertThat(join.getKubernetesConfig().getProperty("service-dns")).isEqualTo("studio-cluster.ns.svc.cluster.local");
        assertThat(join.getKubernetesConfig().getProperty("service-port")).isEqualTo("5701");
        assertThat(join.getTcpIpConfig().isEnabled()).isFalse();
        assertThat(join.getMulticastConfig().isEnabled()).isFalse();
        assertThat(join.getAutoDetectionConfig().isEnabled()).isFalse();
    }

    @Test
    void aListAndKubernetesTogetherAreRefused() {
        assertThatThrownBy(() -> new ClusterProperties(5701, List.of("a:5701"), "n", "", "studio-cluster", TestMember.SECRET, false))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("studio.cluster.members or studio.cluster.kubernetes-service-dns");
    }

    @Test
    void aMemberStartsWithAListOrAServiceNameAndNotWithout() {
        assertThat(configured(new MockEnvironment())).isFalse();
        assertThat(configured(new MockEnvironment().withProperty("studio.cluster.members", " "))).isFalse();
        assertThat(configured(new MockEnvironment().withProperty("studio.cluster.members", "a:5701"))).isTrue();
        assertThat(configured(new MockEnvironment().withProperty("studio.cluster.kubernetes-service-dns", "s"))).isTrue();
        assertThat(configured(new MockEnvironment().withProperty("studio.cluster.kubernetes-service-dns", ""))).isFalse();
    }

    private static boolean configured(MockEnvironment environment) {
        ConditionContext context = mock(ConditionContext.class);
        when(context.getEnvironment()).thenReturn(environment);
        return new ClusterConfiguration.MembersConfigured().matches(context, null);
    }
}

package studio.server.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.springframework.boot.autoconfigure.AutoConfigurations;
import org.springframework.boot.hazelcast.autoconfigure.HazelcastAutoConfiguration;
import org.springframework.boot.health.contributor.Health;
import org.springframework.boot.test.context.runner.ApplicationContextRunner;

import com.hazelcast.core.Hazelcast;
import com.hazelcast.core.HazelcastInstance;

import org.springframework.boot.context.properties.EnableConfigurationProperties;

import studio.server.Await;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.system.MemoryBudget;
import studio.server.system.StudioProperties;

/**
 * The member Spring Boot's Hazelcast support starts from studio.cluster.*: none without members, a
 * member on the configured address and port with them, which another member joins.
 */
class ClusterMemberTest {

    private final ApplicationContextRunner context = new ApplicationContextRunner()
            .withConfiguration(AutoConfigurations.of(HazelcastAutoConfiguration.class))
            .withUserConfiguration(ClusterConfiguration.class, Properties.class)
            .withBean(SceneCompiler.class, () -> SceneCompiler.standalone(TestMember.VALIDATION::getValidator))
            .withBean(MemoryBudget.class, MemoryBudget::unlimited);

    @EnableConfigurationProperties(StudioProperties.class)
    static class Properties {
    }

    @Test
    void startsNoMemberWithoutMembers() {
        context.run(started -> {
            assertThat(started).doesNotHaveBean(HazelcastInstance.class);
            Health health = started.getBean(ClusterHealth.class).health();
            assertThat(health.getDetails()).containsEntry("members", 1).containsEntry("member", "none");
        });
    }

    @Test
    void startsAMemberOnTheConfiguredPortThatOthersJoin() {
        context.withPropertyValues("studio.cluster.members=127.0.0.1:5790,127.0.0.1:5791", "studio.cluster.port=5790",
                "studio.cluster.bind-address=127.0.0.1", "studio.cluster.name=member-test",
                "studio.cluster.secret=" + TestMember.SECRET).run(started -> {
            HazelcastInstance member = started.getBean(HazelcastInstance.class);
            ClusterHealth health = started.getBean(ClusterHealth.class);
            assertThat(health.health().getDetails()).containsEntry("members", 1)
                    .containsEntry("member", "127.0.0.1:5790").doesNotContainKey("name");
            assertThat(health.health().getDetails().values().toString()).doesNotContain("member-test");
            HazelcastInstance other = Hazelcast.newHazelcastInstance(MemberConfig.of(
                    TestMember.properties("member-test", 5791, 5790)));
            try {
                Await.until("two members", 30_000, () -> member.getCluster().getMembers().size() == 2);
                assertThat(health.health().getDetails()).containsEntry("members", 2);
            } finally {
                other.getLifecycleService().terminate();
            }
        });
    }

    @Test
    void aClusteredMemberWithoutASecretRefusesToStartSayingWhy() {
        context.withPropertyValues("studio.cluster.members=127.0.0.1:5790", "studio.cluster.port=5790",
                "studio.cluster.bind-address=127.0.0.1").run(started -> {
            assertThat(started).hasFailed();
            assertThat(started.getStartupFailure()).rootCause().isInstanceOf(IllegalStateException.class)
                    .hasMessageStartingWith("a clustered member needs studio.cluster.secret");
        });
        context.withPropertyValues("studio.cluster.kubernetes-service-dns=studio-cluster.ns.svc.cluster.local")
                .run(started -> assertThat(started).hasFailed());
    }

    @Test
    void aMissingSecretIsReportedInOneLineNotAStackTrace() {
        var analysis = new ClusterSecretFailureAnalyzer().analyze(new IllegalStateException("the bean failed",
                new ClusterSecret.Refused("a clustered member needs studio.cluster.secret")));
        assertThat(analysis.getDescription()).isEqualTo("a clustered member needs studio.cluster.secret");
        assertThat(analysis.getAction()).contains("STUDIO_CLUSTER_SECRET");
    }

    @Test
    void aSecretShorterThan32BytesIsRefused() {
        context.withPropertyValues("studio.cluster.members=127.0.0.1:5790", "studio.cluster.port=5790",
                "studio.cluster.bind-address=127.0.0.1", "studio.cluster.secret=short").run(started -> {
            assertThat(started).hasFailed();
            assertThat(started.getStartupFailure()).rootCause().hasMessageContaining("at least 32");
        });
    }

    @Test
    void anInsecureDemoStartsWithoutASecret() {
        context.withPropertyValues("studio.cluster.members=127.0.0.1:5790", "studio.cluster.port=5790",
                "studio.cluster.bind-address=127.0.0.1", "studio.cluster.insecure=true").run(started -> {
            assertThat(started).hasNotFailed();
            assertThat(started.getBean(ClusterSecret.class).insecure()).isTrue();
        });
    }
}

package studio.server.cluster;

import org.springframework.beans.factory.ObjectProvider;
import org.springframework.boot.context.properties.EnableConfigurationProperties;
import org.springframework.boot.context.properties.bind.Bindable;
import org.springframework.boot.context.properties.bind.Binder;
import org.springframework.context.annotation.Bean;
import org.springframework.context.annotation.Condition;
import org.springframework.context.annotation.ConditionContext;
import org.springframework.context.annotation.Conditional;
import org.springframework.context.annotation.Configuration;
import org.springframework.core.type.AnnotatedTypeMetadata;

import com.hazelcast.config.Config;
import com.hazelcast.core.HazelcastInstance;

/**
 * The cluster: with {@code studio.cluster.members} set, a Hazelcast {@link Config} from which
 * Spring Boot's Hazelcast support starts the embedded member; without, nothing (a cluster of one).
 */
@Configuration(proxyBeanMethods = false)
@EnableConfigurationProperties(ClusterProperties.class)
class ClusterConfiguration {

    @Bean
    @Conditional(MembersConfigured.class)
    Config hazelcastConfig(ClusterProperties cluster) {
        return MemberConfig.of(cluster);
    }

    @Bean
    ClusterHealth clusterHealthIndicator(ObjectProvider<HazelcastInstance> member) {
        return new ClusterHealth(member.getIfAvailable());
    }

    /** True when studio.cluster.members names at least one member. */
    static final class MembersConfigured implements Condition {

        @Override
        public boolean matches(ConditionContext context, AnnotatedTypeMetadata metadata) {
            return Binder.get(context.getEnvironment()).bind("studio.cluster.members", Bindable.listOf(String.class))
                    .map(members -> members.stream().anyMatch(member -> !member.isBlank()))
                    .orElse(false);
        }
    }
}

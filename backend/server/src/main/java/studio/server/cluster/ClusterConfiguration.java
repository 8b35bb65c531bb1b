package studio.server.cluster;

import java.time.Duration;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import io.micrometer.core.instrument.Gauge;
import io.micrometer.core.instrument.MeterRegistry;
import io.micrometer.core.instrument.binder.MeterBinder;
import io.micrometer.core.instrument.simple.SimpleMeterRegistry;
import org.springframework.beans.factory.ObjectProvider;
import org.springframework.boot.context.properties.EnableConfigurationProperties;
import org.springframework.boot.context.properties.bind.Bindable;
import org.springframework.boot.context.properties.bind.Binder;
import org.springframework.context.annotation.Bean;
import org.springframework.context.annotation.Condition;
import org.springframework.context.annotation.ConditionContext;
import org.springframework.context.annotation.Conditional;
import org.springframework.context.annotation.Configuration;
import org.springframework.core.env.Environment;
import org.springframework.core.type.AnnotatedTypeMetadata;

import com.hazelcast.config.Config;
import com.hazelcast.core.HazelcastInstance;

import studio.server.asset.SharedAssets;
import studio.server.job.JobCluster;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.system.MemoryBudget;
import studio.server.system.StudioProperties;

/**
 * The cluster: with {@code studio.cluster.members} (or {@code studio.cluster.kubernetes-service-dns})
 * set, a Hazelcast {@link Config} from which Spring Boot's Hazelcast support starts the embedded
 * member, which admits only members holding the cluster's secret and seals all it shares with it
 * ({@link ClusterSecret}, {@link Seal}); without, nothing (a cluster of one).
 */
@Configuration(proxyBeanMethods = false)
@EnableConfigurationProperties(ClusterProperties.class)
class ClusterConfiguration {

    private static final Logger log = LoggerFactory.getLogger(ClusterConfiguration.class);

    @Bean
    @Conditional(MembersConfigured.class)
    ClusterSecret clusterSecret(ClusterProperties cluster) {
        ClusterSecret secret = ClusterSecret.of(cluster);
        if (secret.insecure()) {
            log.warn("studio.cluster.insecure=true: the cluster runs without a secret; anyone who reaches a member's "
                    + "port can join it and read, forge or delete its jobs. Set STUDIO_CLUSTER_SECRET outside a demo.");
        }
        return secret;
    }

    @Bean
    @Conditional(MembersConfigured.class)
    Config hazelcastConfig(ClusterProperties cluster, ClusterSecret secret, StudioProperties properties) {
        HazelcastCompiles.keepOutOfC2(); // before the member starts: none of its code is hot yet
        return MemberConfig.withAssets(MemberConfig.of(cluster, secret), properties.assets().maxStoreBytes().toBytes());
    }

    /** The assets uploaded to any member, for every member's asset store to read (docs/cluster.md). */
    @Bean
    @Conditional(MembersConfigured.class)
    SharedAssets sharedAssets(HazelcastInstance member, ClusterSecret secret, ObjectProvider<MeterRegistry> registry) {
        Seal seal = new Seal(secret, registry.getIfAvailable(SimpleMeterRegistry::new));
        return new ClusterAssets(new ClusterData(member, seal).assets());
    }

    /** Jobs in the cluster's maps, rendered by every member's tile workers (as many as a render's threads). */
    @Bean(destroyMethod = "close")
    @Conditional(MembersConfigured.class)
    JobCluster clusterJobs(HazelcastInstance member, ClusterSecret secret, ObjectProvider<MeterRegistry> registry,
                           SceneCompiler compiler, MemoryBudget memory, StudioProperties properties) {
        int threads = properties.renderThreads() > 0 ? properties.renderThreads()
                : Runtime.getRuntime().availableProcessors();
        Seal seal = new Seal(secret, registry.getIfAvailable(SimpleMeterRegistry::new));
        warmUp(seal);
        ClusterData data = new ClusterData(member, seal);
        TileWorkers workers = new TileWorkers(data, new JobScenes(data.scenes(), compiler, memory), threads);
        return new ClusterJobs(compiler, workers, properties.renderThreads());
    }

    /**
     * At start-up, after the member has joined and before the port opens: a tiny scene through this
     * member's own cluster path, for at most {@code studio.cluster.warm-up} (by default
     * {@code studio.warm-up}; {@code 0s} turns it off).
     */
    @Bean
    @Conditional(MembersConfigured.class)
    ClusterWarmUp clusterWarmUp(HazelcastInstance member, ClusterSecret secret, ObjectProvider<MeterRegistry> registry,
                                SceneCompiler compiler, MemoryBudget memory, StudioProperties properties,
                                Environment environment) {
        Seal seal = new Seal(secret, registry.getIfAvailable(SimpleMeterRegistry::new));
        Duration limit = Binder.get(environment).bind("studio.cluster.warm-up", Duration.class)
                .orElse(properties.warmUp());
        return new ClusterWarmUp(new ClusterData(member, seal), compiler, memory, limit);
    }

    /**
     * Seals and opens {@value #WARM_UP_VALUES} tile-sized values on a background thread at start-up:
     * about 0.8 s of CPU once, which each member otherwise spent in its first jobs' tiles (the
     * per-thread CPU of two pinned members, docs/cluster.md, "What the seal costs").
     */
    private static void warmUp(Seal seal) {
        Thread thread = new Thread(() -> seal.warmUp(WARM_UP_VALUES, WARM_UP_BYTES), "seal-warm-up");
        thread.setDaemon(true);
        thread.setPriority(Thread.MIN_PRIORITY);
        thread.start();
    }

    /** Values sealed and opened at start-up: past the two rounds of 180 a fresh JVM needs to compile AES-GCM. */
    static final int WARM_UP_VALUES = 400;
    /** A 64x64 tile's result, encoded: what the seal handles most, by far. */
    static final int WARM_UP_BYTES = 98_386;

    @Bean
    ClusterHealth clusterHealthIndicator(ObjectProvider<HazelcastInstance> member) {
        return new ClusterHealth(member.getIfAvailable());
    }

    /** The cluster's size as this member sees it, in the metrics: studio_cluster_members. */
    @Bean
    MeterBinder clusterMetrics(ClusterHealth health) {
        return registry -> Gauge.builder("studio.cluster.members", health, ClusterHealth::members)
                .description("Members of the cluster as this member sees it (1: a cluster of one)").register(registry);
    }

    /**
     * True when studio.cluster.members names at least one member, or the members are found on
     * Kubernetes (studio.cluster.kubernetes-service-dns).
     */
    static final class MembersConfigured implements Condition {

        @Override
        public boolean matches(ConditionContext context, AnnotatedTypeMetadata metadata) {
            // the properties' own rule, bound here because a condition runs before their bean exists
            return Binder.get(context.getEnvironment()).bind("studio.cluster", Bindable.of(ClusterProperties.class))
                    .map(ClusterProperties::clustered)
                    .orElse(false);
        }
    }
}

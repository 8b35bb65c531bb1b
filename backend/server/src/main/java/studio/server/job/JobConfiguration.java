package studio.server.job;

import io.micrometer.core.instrument.Gauge;
import io.micrometer.core.instrument.binder.MeterBinder;
import org.springframework.beans.factory.ObjectProvider;
import org.springframework.context.annotation.Bean;
import org.springframework.context.annotation.Configuration;

import studio.server.render.RenderBudget;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.system.StudioProperties;

/** The render jobs (studio.jobs.*), in a cluster with the cluster's jobs. */
@Configuration(proxyBeanMethods = false)
class JobConfiguration {

    /** In a cluster, with the cluster's jobs (studio.server.cluster); else with this member's only. */
    @Bean(destroyMethod = "close")
    JobService jobService(SceneCompiler compiler, StudioProperties properties, RenderBudget budget,
                          ObjectProvider<JobCluster> cluster) {
        return new JobService(compiler, settings(properties), budget, properties.jobs().shutdownGrace(),
                cluster.getIfAvailable(() -> JobCluster.SINGLE));
    }

    /** This member's jobs in the metrics: studio_jobs_queued (the queue's depth) and studio_jobs_running. */
    @Bean
    MeterBinder jobMetrics(JobService jobs) {
        return registry -> {
            Gauge.builder("studio.jobs.queued", jobs, JobService::queued)
                    .description("Render jobs of this member waiting to run").register(registry);
            Gauge.builder("studio.jobs.running", jobs, JobService::running)
                    .description("Render jobs of this member running now").register(registry);
        };
    }

        /** The job settings, with this service's threads per render. */
    static JobSettings settings(StudioProperties properties) {
        StudioProperties.Jobs jobs = properties.jobs();
        return new JobSettings(jobs.concurrent(), jobs.queue(), jobs.keepFinished(), jobs.maxFinished(),
                jobs.abandonAfter(), properties.renderThreads());
    }
}

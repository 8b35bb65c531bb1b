package studio.server.system;

import java.util.List;

import org.springframework.beans.factory.ObjectProvider;
import org.springframework.boot.context.properties.EnableConfigurationProperties;
import org.springframework.boot.web.servlet.FilterRegistrationBean;
import org.springframework.context.annotation.Bean;
import org.springframework.context.annotation.Configuration;

import jakarta.validation.Validator;

import studio.server.job.JobCluster;
import studio.server.job.JobService;
import studio.server.render.RenderBudget;
import studio.server.render.RenderService;
import studio.server.scene.compiling.MeshCache;
import studio.server.scene.compiling.MeshFiles;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.compiling.SceneMapper;
import studio.server.scene.examples.ExampleScenes;
import studio.server.scene.format.SceneLimits;
import studio.server.scene.reading.SceneReader;

/** Wires the scene pipeline and the render service from the configuration. */
@Configuration(proxyBeanMethods = false)
@EnableConfigurationProperties(StudioProperties.class)
class StudioConfiguration {

    @Bean
    SceneLimits sceneLimits(StudioProperties properties) {
        return properties.limits().toSceneLimits();
    }

    @Bean
    SceneCompiler sceneCompiler(Validator validator, SceneLimits limits, MemoryBudget memory) {
        return new SceneCompiler(new SceneReader(validator), new SceneMapper(limits, meshCache(limits, memory)),
                MeshFiles.bundled());
    }

    /** Meshes kept for scenes that send them again (the live view does on every edit): an eighth of the render memory. */
    private static MeshCache meshCache(SceneLimits limits, MemoryBudget memory) {
        long triangles = memory.capacity() / 8 / MeshCache.BYTES_PER_TRIANGLE;
        return new MeshCache(Math.min(limits.maxTriangles(), triangles), memory);
    }

    @Bean
    MemoryBudget memoryBudget(StudioProperties properties) {
        return properties.memoryBudget();
    }

    @Bean
    RenderBudget renderBudget(StudioProperties properties, MemoryBudget memory) {
        return new RenderBudget(properties.limits().maxRenderTime(), memory);
    }

    @Bean(destroyMethod = "close")
    RenderService renderService(SceneCompiler compiler, StudioProperties properties, RenderBudget budget) {
        return new RenderService(compiler, properties.concurrentRenders(), properties.renderThreads(), budget);
    }

    /** In a cluster, with the cluster's jobs (studio.server.cluster); else with this member's only. */
    @Bean(destroyMethod = "close")
    JobService jobService(StudioProperties properties, RenderBudget budget, ObjectProvider<JobCluster> cluster) {
        return new JobService(properties.jobSettings(), budget, properties.jobs().shutdownGrace(),
                cluster.getIfAvailable(() -> JobCluster.SINGLE));
    }

    @Bean
    GracefulShutdown gracefulShutdown(RenderService renders, JobService jobs, StudioProperties properties) {
        return new GracefulShutdown(List.of(renders, jobs), properties.jobs().shutdownGrace());
    }

    @Bean
    ExampleScenes exampleScenes() {
        return ExampleScenes.fromClasspath();
    }

    @Bean
    FilterRegistrationBean<BodySizeLimitFilter> bodySizeLimitFilter(StudioProperties properties) {
        FilterRegistrationBean<BodySizeLimitFilter> registration =
                new FilterRegistrationBean<>(new BodySizeLimitFilter(properties.limits().maxBodyBytes()));
        registration.addUrlPatterns("/api/*");
        registration.setOrder(1);
        return registration;
    }

    @Bean
    FilterRegistrationBean<IntakeMemoryFilter> intakeMemoryFilter(MemoryBudget memory) {
        FilterRegistrationBean<IntakeMemoryFilter> registration = new FilterRegistrationBean<>(new IntakeMemoryFilter(memory));
        registration.addUrlPatterns("/api/*");
        registration.setOrder(2);
        return registration;
    }

    @Bean
    FilterRegistrationBean<BodyDeadlineFilter> bodyDeadlineFilter(StudioProperties properties) {
        FilterRegistrationBean<BodyDeadlineFilter> registration = new FilterRegistrationBean<>(
                new BodyDeadlineFilter(properties.limits().bodyGrace(), properties.limits().minBodyRate()));
        registration.addUrlPatterns("/api/*");
        registration.setOrder(3);
        return registration;
    }

    @Bean
    RenderMemoryHealth renderMemoryHealthIndicator(MemoryBudget memory) {
        return new RenderMemoryHealth(memory);
    }
}

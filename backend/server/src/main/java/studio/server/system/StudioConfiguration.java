package studio.server.system;

import org.springframework.boot.context.properties.EnableConfigurationProperties;
import org.springframework.boot.web.servlet.FilterRegistrationBean;
import org.springframework.context.annotation.Bean;
import org.springframework.context.annotation.Configuration;

import jakarta.validation.Validator;
import studio.server.job.JobService;
import studio.server.render.RenderBudget;
import studio.server.render.RenderService;
import studio.server.scene.ExampleScenes;
import studio.server.scene.MeshFiles;
import studio.server.scene.SceneCompiler;
import studio.server.scene.SceneLimits;
import studio.server.scene.SceneMapper;
import studio.server.scene.SceneReader;

/** Wires the scene pipeline and the render service from the configuration. */
@Configuration(proxyBeanMethods = false)
@EnableConfigurationProperties(StudioProperties.class)
class StudioConfiguration {

    @Bean
    SceneLimits sceneLimits(StudioProperties properties) {
        return properties.limits().toSceneLimits();
    }

    @Bean
    SceneCompiler sceneCompiler(Validator validator, SceneLimits limits) {
        return new SceneCompiler(new SceneReader(validator), new SceneMapper(limits), MeshFiles.bundled());
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

    @Bean(destroyMethod = "close")
    JobService jobService(StudioProperties properties, RenderBudget budget) {
        return new JobService(properties.jobSettings(), budget, properties.jobs().shutdownGrace());
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

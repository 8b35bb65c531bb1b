package studio.server.system;

import java.util.List;

import org.springframework.boot.context.properties.EnableConfigurationProperties;
import org.springframework.boot.web.servlet.FilterRegistrationBean;
import org.springframework.context.annotation.Bean;
import org.springframework.context.annotation.Configuration;

/**
 * The service's own machinery, from the configuration: the memory budget, the filters every
 * request body passes, graceful shutdown of whatever work the features hand in ({@link Drainable}
 * beans), and the memory's health. Each feature wires its own beans (SceneConfiguration,
 * RenderConfiguration, JobConfiguration, ...) from the same {@link StudioProperties}.
 */
@Configuration(proxyBeanMethods = false)
@EnableConfigurationProperties(StudioProperties.class)
class SystemConfiguration {

    @Bean
    MemoryBudget memoryBudget(StudioProperties properties) {
        return properties.memoryBudget();
    }

    /** The synchronous renders and the jobs: all of the features' work that shutdown lets finish. */
    @Bean
    GracefulShutdown gracefulShutdown(List<Drainable> work, StudioProperties properties) {
        return new GracefulShutdown(work, properties.jobs().shutdownGrace());
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

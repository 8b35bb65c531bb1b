package studio.server.system;

import java.util.List;

import io.micrometer.core.instrument.Gauge;
import io.micrometer.core.instrument.MeterRegistry;
import io.micrometer.core.instrument.binder.MeterBinder;
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

    /**
     * The API's refusals counted by status, first of the filters so that it sees theirs: before Spring
     * Security's too (spring.security.filter.order, -100), so that sign-in's 401s count.
     */
    @Bean
    FilterRegistrationBean<RefusalMetricsFilter> refusalMetricsFilter(MeterRegistry registry) {
        FilterRegistrationBean<RefusalMetricsFilter> registration =
                new FilterRegistrationBean<>(new RefusalMetricsFilter(registry));
        registration.addUrlPatterns("/api/*");
        registration.setOrder(-101);
        return registration;
    }

    /**
     * The render memory in the metrics: studio_render_memory_capacity_bytes, _reserved_bytes and
     * _free_bytes (what renders, jobs, live views and request bodies hold, and what is left), and
     * studio_render_memory_kept (how many holdings are only kept, and yield).
     */
    @Bean
    MeterBinder renderMemoryMetrics(MemoryBudget memory) {
        return registry -> {
            Gauge.builder("studio.render.memory.capacity", memory, MemoryBudget::capacity).baseUnit("bytes")
                    .description("The render memory (studio.render-memory)").register(registry);
            Gauge.builder("studio.render.memory.reserved", memory, MemoryBudget::reserved).baseUnit("bytes")
                    .description("Render memory held by renders, jobs, live views and request bodies")
                    .register(registry);
            Gauge.builder("studio.render.memory.free", memory, m -> m.capacity() - m.reserved()).baseUnit("bytes")
                    .description("Render memory not held").register(registry);
            Gauge.builder("studio.render.memory.kept", memory, MemoryBudget::yieldingCount)
                    .description("Scenes and films kept only to save work (live views'), given back when other work needs the memory")
                    .register(registry);
        };
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

    /**
     * Bodies read before their controller runs, without a thread while they are on their way: the
     * last of the filters, so that the others have seen the request (and watch its body's bytes) first.
     */
    @Bean
    FilterRegistrationBean<BodyArrivalFilter> bodyArrivalFilter(StudioProperties properties) {
        FilterRegistrationBean<BodyArrivalFilter> registration = new FilterRegistrationBean<>(new BodyArrivalFilter(
                properties.limits().bodyGrace(), properties.limits().minBodyRate(), properties.limits().maxBodyBytes()));
        registration.addUrlPatterns("/api/*");
        registration.setOrder(3);
        return registration;
    }

    @Bean
    RenderMemoryHealth renderMemoryHealthIndicator(MemoryBudget memory) {
        return new RenderMemoryHealth(memory);
    }
}

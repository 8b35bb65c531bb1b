package studio.server.render;

import io.micrometer.core.instrument.FunctionCounter;
import io.micrometer.core.instrument.Gauge;
import io.micrometer.core.instrument.MeterRegistry;
import io.micrometer.core.instrument.binder.MeterBinder;
import org.springframework.context.annotation.Bean;
import org.springframework.context.annotation.Configuration;

import studio.server.scene.compiling.SceneCompiler;
import studio.server.system.MemoryBudget;
import studio.server.system.StudioProperties;

/** The render budget every render runs within (its renders counted in the service's metrics), the synchronous render service (POST /api/render) with its metrics, and the start-up warm-up. */
@Configuration(proxyBeanMethods = false)
class RenderConfiguration {

    @Bean
    RenderBudget renderBudget(StudioProperties properties, MemoryBudget memory, MeterRegistry metrics) {
        return new RenderBudget(properties.limits().maxRenderTime(), memory, new RenderMetrics(metrics));
    }

    @Bean
    RenderWarmUp renderWarmUp(SceneCompiler compiler, StudioProperties properties, RenderBudget budget) {
        return new RenderWarmUp(compiler, budget, properties.renderThreads(), properties.warmUp());
    }

    @Bean(destroyMethod = "close")
    RenderService renderService(SceneCompiler compiler, StudioProperties properties, RenderBudget budget) {
        return new RenderService(compiler, properties.concurrentRenders(), properties.renderThreads(), budget);
    }

    /**
     * The synchronous renders in the metrics: studio_render_requests_active (running or about to
     * run, at most studio.concurrent-renders) and studio_render_requests_cancelled_total (stopped
     * because their client went away, or the service stopped).
     */
    @Bean
    MeterBinder renderRequestMetrics(RenderService renders) {
        return registry -> {
            Gauge.builder("studio.render.requests.active", renders, RenderService::active)
                    .description("Synchronous renders (POST /api/render) running or about to run").register(registry);
            FunctionCounter.builder("studio.render.requests.cancelled", renders, RenderService::cancelled)
                    .description("Synchronous renders stopped because their client went away or the service stopped")
                    .register(registry);
        };
    }
}

package studio.server.render;

import io.micrometer.core.instrument.MeterRegistry;
import org.springframework.context.annotation.Bean;
import org.springframework.context.annotation.Configuration;

import studio.server.scene.compiling.SceneCompiler;
import studio.server.system.MemoryBudget;
import studio.server.system.StudioProperties;

/** The render budget every render runs within (its renders counted in the service's metrics), the synchronous render service (POST /api/render), and the start-up warm-up. */
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
}

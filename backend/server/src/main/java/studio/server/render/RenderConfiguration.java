package studio.server.render;

import org.springframework.context.annotation.Bean;
import org.springframework.context.annotation.Configuration;

import studio.server.scene.compiling.SceneCompiler;
import studio.server.system.MemoryBudget;
import studio.server.system.StudioProperties;

/** The render budget every render runs within, and the synchronous render service (POST /api/render). */
@Configuration(proxyBeanMethods = false)
class RenderConfiguration {

    @Bean
    RenderBudget renderBudget(StudioProperties properties, MemoryBudget memory) {
        return new RenderBudget(properties.limits().maxRenderTime(), memory);
    }

    @Bean(destroyMethod = "close")
    RenderService renderService(SceneCompiler compiler, StudioProperties properties, RenderBudget budget) {
        return new RenderService(compiler, properties.concurrentRenders(), properties.renderThreads(), budget);
    }
}

package studio.server.scene.compiling;

import org.springframework.beans.factory.ObjectProvider;
import org.springframework.context.annotation.Bean;
import org.springframework.context.annotation.Configuration;

import jakarta.validation.Validator;
import studio.server.scene.format.SceneLimits;
import studio.server.scene.reading.SceneReader;
import studio.server.system.MemoryBudget;
import studio.server.system.StudioProperties;

/** The scene pipeline of the service: its limits (studio.limits.*) and the one compiler every feature uses. */
@Configuration(proxyBeanMethods = false)
class SceneConfiguration {

    @Bean
    SceneLimits sceneLimits(StudioProperties properties) {
        return limits(properties.limits());
    }

    static SceneLimits limits(StudioProperties.Limits l) {
        return new SceneLimits(l.maxWidth(), l.maxHeight(), l.maxSamples(), l.maxDepth(), l.maxObjects(),
                l.maxLights(), l.maxTriangles(), l.maxBodyBytes(), l.maxPixelSamples());
    }

    /**
     * Reads the meshes shipped with the example scenes, and meshes' and images' assets from the asset
     * feature (none without it); keeps meshes, and textures' decoded images (an eighth of the render
     * memory each), for scenes that send them again.
     */
    @Bean
    SceneCompiler sceneCompiler(Validator validator, SceneLimits limits, MemoryBudget memory,
                                ObjectProvider<MeshAssets> assets, ObjectProvider<ImageAssets> images) {
        return new SceneCompiler(new SceneReader(validator), new SceneMapper(limits, meshCache(limits, memory),
                assets.getIfAvailable(MeshAssets::none), new TextureCache(memory.capacity() / 8, memory),
                images.getIfAvailable(ImageAssets::none)), MeshFiles.bundled());
    }

    /** Meshes kept for scenes that send them again (the live view does on every edit): an eighth of the render memory. */
    private static MeshCache meshCache(SceneLimits limits, MemoryBudget memory) {
        long triangles = memory.capacity() / 8 / MeshCache.BYTES_PER_TRIANGLE;
        return new MeshCache(Math.min(limits.maxTriangles(), triangles), memory);
    }
}

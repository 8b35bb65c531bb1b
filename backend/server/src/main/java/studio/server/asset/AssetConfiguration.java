package studio.server.asset;

import org.springframework.beans.factory.ObjectProvider;
import org.springframework.context.annotation.Bean;
import org.springframework.context.annotation.Configuration;

import studio.server.scene.compiling.ImageAssets;
import studio.server.scene.compiling.MeshAssets;
import studio.server.system.MemoryBudget;
import studio.server.system.StudioProperties;

/** The asset store (studio.assets.*) and how the scene compiler reads meshes' assets from it. */
@Configuration(proxyBeanMethods = false)
class AssetConfiguration {

    @Bean
    AssetLimits assetLimits(StudioProperties properties, MemoryBudget memory) {
        StudioProperties.Assets assets = properties.assets();
        return AssetLimits.of(assets.maxBytes().toBytes(), assets.maxStoreBytes().toBytes(), memory.capacity());
    }

    @Bean
    AssetChecks assetChecks(StudioProperties properties) {
        return new AssetChecks(properties.limits().maxTriangles(), properties.assets().maxPixels());
    }

    /** This member's assets, backed by the cluster's copy when the cluster feature offers one. */
    @Bean
    AssetStore assetStore(AssetLimits limits, MemoryBudget memory, ObjectProvider<SharedAssets> shared) {
        return new LocalAssets(limits.storeBytes(), memory, shared.getIfAvailable(() -> SharedAssets.NONE));
    }

    /** A mesh's asset: its bytes if it is kept and is OBJ. */
    @Bean
    MeshAssets meshAssets(AssetStore store) {
        return store.meshes();
    }

    /** A texture's image asset: its bytes if it is kept and is PNG or JPEG. */
    @Bean
    ImageAssets imageAssets(AssetStore store) {
        return store.images();
    }
}

package studio.server.scene.compiling;

import static studio.server.scene.compiling.FormatValues.or;

import java.util.List;

import studio.engine.camera.Camera;
import studio.engine.light.Light;
import studio.engine.memory.MemoryGate;
import studio.engine.render.RenderSettings;
import studio.engine.scene.MeshLightBuffers;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;
import studio.server.scene.format.InvalidSceneException;
import studio.server.scene.format.SceneDefaults;
import studio.server.scene.format.SceneDto;
import studio.server.scene.format.SceneLimits;
import studio.server.scene.format.SceneNames;

/**
 * Maps a validated scene DTO onto the engine, part by part, each in the one place its DTO types
 * meet their engine types: {@link RenderMapping} (image and render settings), {@link ObjectMapping}
 * (shapes, with {@link MeshMapping} for meshes, and {@link MaterialMapping}), {@link LightMapping}
 * and {@link CameraMapping}. Each fills in defaults, checks the configured limits and the rules that
 * span fields, and reports every problem by its JSON path before anything is rendered.
 *
 * <p>The memory mapping takes is asked of a {@link MemoryGate} first (see {@link ObjectMapping}).
 */
public final class SceneMapper {

    private final SceneLimits limits;
    private final MeshCache meshes;
    private final MeshAssets assets;
    private final TextureCache images;
    private final ImageAssets imageAssets;

    public SceneMapper(SceneLimits limits) {
        this(limits, MeshCache.none());
    }

    /** @param meshes meshes already read and built, reused when a scene has them unchanged */
    public SceneMapper(SceneLimits limits, MeshCache meshes) {
        this(limits, meshes, MeshAssets.none());
    }

    /** @param assets where meshes' {@code asset} ids are read from */
    public SceneMapper(SceneLimits limits, MeshCache meshes, MeshAssets assets) {
        this(limits, meshes, assets, TextureCache.none(), ImageAssets.none());
    }

    /** @param images images decoded for textures, reused when a scene names them again; imageAssets: where they are read from */
    public SceneMapper(SceneLimits limits, MeshCache meshes, MeshAssets assets, TextureCache images,
                       ImageAssets imageAssets) {
        this.limits = limits;
        this.meshes = meshes;
        this.assets = assets;
        this.images = images;
        this.imageAssets = imageAssets;
    }

    /** As {@link #map(SceneDto, int, MeshFiles)}, with no mesh files (inline meshes only). */
    public CompiledScene map(SceneDto dto, int threads) {
        return map(dto, threads, MeshFiles.none());
    }

    /** As {@link #map(SceneDto, int, MeshFiles, MemoryGate)}, without a memory limit. */
    public CompiledScene map(SceneDto dto, int threads, MeshFiles meshFiles) {
        return map(dto, threads, meshFiles, MemoryGate.UNLIMITED);
    }

    /**
     * @param threads    worker threads for the render (0: all cores); not part of the scene format
     * @param meshFiles  where a mesh's {@code file} is read from
     * @param memory     asked before the engine objects, the meshes' arrays and their light buffers are allocated
     * @throws InvalidSceneException listing every problem found, in the order of the parts below
     */
    public CompiledScene map(SceneDto dto, int threads, MeshFiles meshFiles, MemoryGate memory) {
        MappingProblems problems = new MappingProblems();
        RenderMapping render = RenderMapping.of(dto.image(), dto.render(), limits, problems);
        List<SceneObject> objects = new ObjectMapping(limits, meshes, meshFiles, assets, images, imageAssets, memory,
                problems).of(dto.objects());
        List<Light> lights = LightMapping.of(dto.lights(), limits, problems);
        Camera camera = CameraMapping.of(dto.camera(), problems);
        problems.throwIfAny();

        RenderSettings settings = render.settings(threads);
        List<SceneObject> lit = MeshLightBuffers.forRender(objects, lights, settings.cameraSamples(), memory);
        Scene scene = new Scene(camera, lit, lights, Colors.linear(or(dto.background(), SceneDefaults.BACKGROUND)),
                or(dto.ambient(), SceneDefaults.AMBIENT));
        return new CompiledScene(scene, settings, render.format(), render.quality(), SceneNames.toFileStem(dto.name()));
    }
}

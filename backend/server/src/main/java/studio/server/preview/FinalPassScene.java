package studio.server.preview;

import java.util.ArrayList;
import java.util.List;

import studio.engine.memory.MemoryGate;
import studio.engine.scene.MeshLightBuffers;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;
import studio.server.scene.compiling.CompiledScene;

/**
 * The meshes' light buffers of a revision assembled from the kept scene, built when its final
 * pass begins rather than with the scene. They pay only for a render of many samples a triangle
 * ({@link MeshLightBuffers}): the one-sample passes of a 640x480 view (307,200 camera samples) do
 * without them for any mesh of more than 38,400 triangles, and a drag's revisions seldom reach
 * their final pass. Building them for a 50,000-triangle mesh moved, two lights, took about 12 of
 * the 17 ms of CPU its revision took to compile ({@code PatchRevisionBench --mesh} in the tests).
 * The buffers change no pixel (a shadow ray is blocked exactly when the mesh's tree says so), so
 * the final frame stays the one {@code POST /api/render} gives, which builds them the same way.
 */
final class FinalPassScene {

    private FinalPassScene() {
    }

    /** Camera samples of a view's one-sample passes in all: one a pixel, whatever the mosaic's order. */
    static long oneSamplePasses(CompiledScene frame) {
        return (long) frame.settings().width() * frame.settings().height();
    }

    /**
     * The scene with the light buffers its own render settings pay for, its tree refitted where a
     * mesh got some ({@link Scene#reusing}); the same scene where none does, or every one has them.
     */
    static CompiledScene of(CompiledScene compiled, MemoryGate memory) {
        Scene scene = compiled.scene();
        List<SceneObject> objects = new ArrayList<>(scene.objectCount());
        for (int i = 0; i < scene.objectCount(); i++) {
            objects.add(new SceneObject(scene.shape(i), scene.material(i)));
        }
        List<SceneObject> lit = MeshLightBuffers.forRender(objects, scene.lights(), compiled.settings().cameraSamples(), memory);
        boolean same = true;
        for (int i = 0; i < lit.size() && same; i++) {
            same = lit.get(i).shape() == scene.shape(i);
        }
        return same ? compiled : new CompiledScene(Scene.reusing(scene, scene.camera(), lit, scene.lights(),
                scene.background(), scene.ambient()), compiled.settings(), compiled.format(), compiled.quality(),
                compiled.fileStem());
    }
}

package studio.server.preview;

import java.util.ArrayList;
import java.util.List;

import studio.engine.memory.MemoryGate;
import studio.engine.scene.MeshLightBuffers;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;
import studio.server.scene.compiling.CompiledScene;

/**
 * The meshes' light buffers of a revision assembled from the kept scene, built once its first,
 * coarsest frame is out (when its second pass begins) rather than with the scene. Building them
 * for a 50,000-triangle mesh moved, two lights, took about 12 of the 17 ms of CPU its revision
 * took to compile ({@code PatchRevisionBench --mesh} in the tests), which the first frame need not
 * wait for, and a drag's revisions seldom get past their first pass. The later passes have them:
 * the full-size one-sample pass of {@code mesh-50k} came in 195 ms after the one before it with
 * them and 347 without ({@code scripts/LiveViewBench.java}, load 18). They change no pixel (a
 * shadow ray is blocked exactly when the mesh's tree says so), so the final frame stays the one
 * {@code POST /api/render} gives, which builds them the same way.
 */
final class DeferredMeshBuffers {

    private DeferredMeshBuffers() {
    }

    /** Camera samples of a view's first pass: one pixel of each 8x8 block. */
    static long firstPass(CompiledScene frame) {
        int step = PreviewPass.COARSE_STEPS[0];
        return (long) (frame.settings().width() / step) * (frame.settings().height() / step);
    }

    /**
     * The scene with the light buffers its own render settings (the final pass's) pay for, its tree refitted where a
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

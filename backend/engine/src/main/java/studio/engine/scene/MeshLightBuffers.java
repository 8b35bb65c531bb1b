package studio.engine.scene;

import java.util.List;

import studio.engine.geometry.TriangleMesh;
import studio.engine.light.Light;
import studio.engine.math.Vec3;
import studio.engine.memory.MemoryGate;

/**
 * Which meshes of a scene get light buffers ({@link TriangleMesh#withLightBuffers}) for a render:
 * those with at most one triangle for every {@value #SAMPLES_PER_TRIANGLE} camera samples. Building
 * a mesh's buffers reads all its triangles a few times per light, which a short render does not win
 * back: on the peer benchmark's 104,000-triangle mesh ({@code studio-bench peers}) they save a sixth
 * at 74 camera samples a triangle and nothing at 4.6; the threshold asks about twice that.
 */
public final class MeshLightBuffers {

    /** Camera samples a triangle needs for its mesh's buffers to pay. */
    public static final int SAMPLES_PER_TRIANGLE = 8;

    private MeshLightBuffers() {
    }

    /**
     * The objects, each mesh among them given light buffers for these lights if a render of
     * {@code cameraSamples} camera samples (width x height x samples a pixel) pays for them; the
     * same list if none is.
     */
    public static List<SceneObject> forRender(List<SceneObject> objects, List<? extends Light> lights, long cameraSamples,
                                              MemoryGate memory) {
        if (lights.isEmpty() || objects.stream().noneMatch(o -> pays(o, cameraSamples))) {
            return objects;
        }
        // point lights only: a sphere or area light's shadow rays end all over it, never at one buffered point
        List<Vec3> positions = lights.stream().filter(l -> !l.soft()).map(Light::position).toList();
        return objects.stream()
                .map(o -> pays(o, cameraSamples) ? new SceneObject(
                        ((TriangleMesh) o.shape()).withLightBuffers(positions, memory), o.material()) : o)
                .toList();
    }

    private static boolean pays(SceneObject object, long cameraSamples) {
        return object.shape() instanceof TriangleMesh mesh
                && cameraSamples / SAMPLES_PER_TRIANGLE >= mesh.triangleCount();
    }
}

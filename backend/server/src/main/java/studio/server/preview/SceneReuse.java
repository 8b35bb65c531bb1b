package studio.server.preview;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Function;

import studio.engine.geometry.TriangleMesh;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;
import studio.server.scene.compiling.CompiledScene;
import studio.server.system.MemoryBudget;

/**
 * A live view's last compiled scene, kept to compile the next revision from. A drag sends the
 * whole scene at every step, yet changes one object; when a revision's JSON differs from the kept
 * one's only inside a few elements of its {@code objects} array, only those elements are read
 * (each in a scene of its own: the revision's bytes around the array with that one element) and
 * the scene is assembled from the kept objects and the new ones. That is the scene reading the
 * whole revision gives, to the bit: the rest of the JSON is byte for byte the kept one's, each
 * object maps on its own (its shape and material depend on its element alone), and the engine's
 * objects are immutable. Anything else (another object count, a light, the camera, the view's
 * size, a mesh among the changed, more than {@value #MAX_CHANGED} changed, a changed element that
 * does not read) is read in full, as {@code POST /api/render} reads it, and so are its problems.
 *
 * <p>Kept only for scenes of at least {@value #MIN_OBJECTS} objects, where reading pays (10,000
 * spheres: 20-40 ms), and only while the render memory can hold the kept bytes and objects; the
 * memory is given back when the view closes. {@link #compile} is called by the view's worker, one
 * revision at a time; {@link #close} by any thread, at once.
 */
final class SceneReuse implements AutoCloseable {

    /** Fewer objects than this are read in full: it costs little. */
    static final int MIN_OBJECTS = 256;
    /** More changed objects than this are read in full. */
    static final int MAX_CHANGED = 8;
    /** What a kept object holds besides its JSON, as {@code ObjectMapping} counts it. */
    private static final long BYTES_PER_OBJECT = 640;

    /** The kept revision: its scene's bytes, its objects' ranges in them, the view's size and the scene. */
    private record Kept(byte[] json, int[] objects, int width, int height, CompiledScene compiled,
                        MemoryBudget.Reservation memory) {
    }

    private final MemoryBudget memory;
    private final AtomicReference<Kept> kept = new AtomicReference<>();
    private volatile boolean closed;
    private volatile long reused;

    SceneReuse(MemoryBudget memory) {
        this.memory = memory;
    }

    /**
     * The scene of a revision: assembled from the kept one where only some objects changed, else
     * {@code read} from its whole JSON. {@code read} compiles a scene's JSON at the view's size (and
     * throws as {@code POST /api/render} would refuse it); it is also how each changed object is read.
     */
    CompiledScene compile(PreviewRequest request, Function<byte[], CompiledScene> read) {
        int[] objects = request.objects();
        Kept before = kept.get();
        CompiledScene assembled = objects != null && before != null ? fromKept(before, request, objects, read) : null;
        CompiledScene scene = assembled != null ? assembled : read.apply(request.scene());
        if (assembled != null) {
            reused++;
        }
        keep(request, objects, scene);
        return scene;
    }

    /** Revisions assembled from a kept scene so far. */
    long reused() {
        return reused;
    }

    /** Gives the kept scene's memory back; nothing is kept from now on. */
    @Override
    public void close() {
        closed = true;
        release();
    }

    private CompiledScene fromKept(Kept last, PreviewRequest request, int[] objects, Function<byte[], CompiledScene> read) {
        byte[] json = request.scene(), was = last.json();
        int[] wasObjects = last.objects();
        int n = objects.length / 2;
        Scene scene = last.compiled().scene();
        if (request.width() != last.width() || request.height() != last.height() || objects.length != wasObjects.length
                || scene.objectCount() != n) {
            return null;
        }
        // the bytes around the objects: before the first, between each two and after the last
        if (!Arrays.equals(json, 0, objects[0], was, 0, wasObjects[0])
                || !Arrays.equals(json, objects[2 * n - 1], json.length, was, wasObjects[2 * n - 1], was.length)) {
            return null;
        }
        for (int i = 1; i < n; i++) {
            if (!Arrays.equals(json, objects[2 * i - 1], objects[2 * i], was, wasObjects[2 * i - 1], wasObjects[2 * i])) {
                return null;
            }
        }
        List<Integer> changed = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            if (!Arrays.equals(json, objects[2 * i], objects[2 * i + 1], was, wasObjects[2 * i], wasObjects[2 * i + 1])) {
                if (changed.size() == MAX_CHANGED || scene.shape(i) instanceof TriangleMesh) {
                    return null;
                }
                changed.add(i);
            }
        }
        if (changed.isEmpty()) {
            return last.compiled();
        }
        List<SceneObject> assembled = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            assembled.add(new SceneObject(scene.shape(i), scene.material(i)));
        }
        for (int i : changed) {
            CompiledScene alone;
            try {
                alone = read.apply(alone(json, objects, i));
            } catch (RuntimeException e) {
                return null; // read in full, for the problems by their whole scene's paths
            }
            Scene one = alone.scene();
            if (one.objectCount() != 1 || one.shape(0) instanceof TriangleMesh) {
                return null; // meshes share one triangle limit: read in full
            }
            assembled.set(i, new SceneObject(one.shape(0), one.material(0)));
        }
        CompiledScene before = last.compiled();
        return new CompiledScene(new Scene(scene.camera(), assembled, scene.lights(), scene.background(), scene.ambient()),
                before.settings(), before.format(), before.quality(), before.fileStem());
    }

    /** The scene's JSON with only its object i: the bytes before the first object, object i's, those after the last. */
    private static byte[] alone(byte[] json, int[] objects, int i) {
        int before = objects[0], start = objects[2 * i], end = objects[2 * i + 1], after = objects[objects.length - 1];
        byte[] scene = new byte[before + (end - start) + (json.length - after)];
        System.arraycopy(json, 0, scene, 0, before);
        System.arraycopy(json, start, scene, before, end - start);
        System.arraycopy(json, after, scene, before + end - start, json.length - after);
        return scene;
    }

    private void keep(PreviewRequest request, int[] objects, CompiledScene scene) {
        release();
        if (objects == null || objects.length / 2 < MIN_OBJECTS || closed) {
            return;
        }
        MemoryBudget.Reservation held = memory.tryReserve(request.scene().length + BYTES_PER_OBJECT * objects.length / 2);
        if (held != null) {
            kept.set(new Kept(request.scene(), objects, request.width(), request.height(), scene, held));
            if (closed) {
                release(); // closed meanwhile: whichever of the two swaps it out gives the memory back
            }
        }
    }

    private void release() {
        Kept dropped = kept.getAndSet(null);
        if (dropped != null) {
            dropped.memory().close();
        }
    }
}

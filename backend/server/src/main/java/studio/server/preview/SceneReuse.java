package studio.server.preview;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Function;

import studio.engine.geometry.TriangleMesh;
import studio.engine.memory.MemoryGate;
import studio.engine.scene.MeshLightBuffers;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;
import studio.server.render.RenderMemory;
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
 * memory is given back when the view closes, or when other work finds the memory short (a
 * yielding reservation: the next revision is then read in full). {@link #compile} is called by the view's worker, one
 * revision at a time; {@link #close} by any thread, at once.
 */
final class SceneReuse implements AutoCloseable {

    /** Fewer objects than this are read in full: it costs little. */
    static final int MIN_OBJECTS = 256;
    /** More changed objects than this are read in full. */
    static final int MAX_CHANGED = 8;
    /** Smaller scenes (unless of many objects) are read in full: it costs little. */
    static final int MIN_BYTES = 64 << 10;
    /** Ints an object takes in a request's {@code objects}. */
    private static final int PER = SceneObjectsInJson.PER_OBJECT;
    /** A three-vertex OBJ text, as a JSON string, that stands in for an unchanged mesh's while its other fields are read. */
    private static final byte[] STAND_IN = "\"v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 3\\n\"".getBytes(StandardCharsets.US_ASCII);

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
    CompiledScene compile(PreviewRequest request, MemoryGate memory, Function<byte[], CompiledScene> read) {
        int[] objects = request.objects();
        Kept before = kept.get();
        CompiledScene assembled = objects != null && before != null ? fromKept(before, request, objects, memory, read)
                : null;
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

    private CompiledScene fromKept(Kept last, PreviewRequest request, int[] objects, MemoryGate memory,
                                   Function<byte[], CompiledScene> read) {
        byte[] json = request.scene(), was = last.json();
        int[] wasObjects = last.objects();
        int n = objects.length / PER, count = last.compiled().scene().objectCount();
        Scene scene = last.compiled().scene();
        if (request.width() != last.width() || request.height() != last.height() || objects.length != wasObjects.length
                || count != n) {
            return null;
        }
        // the bytes around the objects: before the first, between each two and after the last
        if (!Arrays.equals(json, 0, objects[0], was, 0, wasObjects[0])
                || !Arrays.equals(json, end(objects, n - 1), json.length, was, end(wasObjects, n - 1), was.length)) {
            return null;
        }
        for (int i = 1; i < n; i++) {
            if (!Arrays.equals(json, end(objects, i - 1), start(objects, i), was, end(wasObjects, i - 1),
                    start(wasObjects, i))) {
                return null;
            }
        }
        List<Integer> changed = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            if (!Arrays.equals(json, start(objects, i), end(objects, i), was, start(wasObjects, i), end(wasObjects, i))) {
                if (changed.size() == MAX_CHANGED) {
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
            SceneObject object = scene.shape(i) instanceof TriangleMesh mesh
                    ? movedMesh(mesh, json, objects, i, was, wasObjects, memory, read)
                    : readAlone(alone(json, objects, json, start(objects, i), end(objects, i)), read);
            if (object == null) {
                return null;
            }
            assembled.set(i, object);
        }
        CompiledScene before = last.compiled();
        List<SceneObject> lit = MeshLightBuffers.forRender(assembled, scene.lights(), before.settings().cameraSamples(), memory);
        return new CompiledScene(new Scene(scene.camera(), lit, scene.lights(), scene.background(), scene.ambient()),
                before.settings(), before.format(), before.quality(), before.fileStem());
    }

    /** Object i read in a scene of its own; null if it does not read or is a mesh (meshes share one triangle limit). */
    private static SceneObject readAlone(byte[] alone, Function<byte[], CompiledScene> read) {
        CompiledScene compiled;
        try {
            compiled = read.apply(alone);
        } catch (RuntimeException e) {
            return null; // read in full, for the problems by their whole scene's paths
        }
        Scene one = compiled.scene();
        if (one.objectCount() != 1 || one.shape(0) instanceof TriangleMesh) {
            return null;
        }
        return new SceneObject(one.shape(0), one.material(0));
    }

    /**
     * An inline mesh whose OBJ text is the kept one's, byte for byte, while something else of it
     * changed: its other fields are read with a three-vertex stand-in for the text (so 3.4 MB of
     * OBJ are neither decoded nor digested again), and if only its position or material changed,
     * the kept mesh is moved there ({@link TriangleMesh#movedTo}: the very mesh reading it in full
     * builds). Null for anything else.
     */
    private static SceneObject movedMesh(TriangleMesh kept, byte[] json, int[] objects, int i, byte[] was,
                                         int[] wasObjects, MemoryGate memory, Function<byte[], CompiledScene> read) {
        int objStart = objects[PER * i + 2], objEnd = objects[PER * i + 3];
        int wasStart = wasObjects[PER * i + 2], wasEnd = wasObjects[PER * i + 3];
        if (objStart < 0 || wasStart < 0 || !Arrays.equals(json, objStart, objEnd, was, wasStart, wasEnd)) {
            return null;
        }
        byte[] element = new byte[(objStart - start(objects, i)) + STAND_IN.length + (end(objects, i) - objEnd)];
        int at = 0;
        System.arraycopy(json, start(objects, i), element, at, objStart - start(objects, i));
        at += objStart - start(objects, i);
        System.arraycopy(STAND_IN, 0, element, at, STAND_IN.length);
        at += STAND_IN.length;
        System.arraycopy(json, objEnd, element, at, end(objects, i) - objEnd);
        CompiledScene compiled;
        try {
            compiled = read.apply(alone(json, objects, element, 0, element.length));
        } catch (RuntimeException e) {
            return null;
        }
        Scene one = compiled.scene();
        if (one.objectCount() != 1 || !(one.shape(0) instanceof TriangleMesh placed) || placed.scale() != kept.scale()
                || !placed.rotationDegrees().equals(kept.rotationDegrees())) {
            return null;
        }
        TriangleMesh moved = placed.position().equals(kept.position()) ? kept : kept.movedTo(placed.position(), memory);
        return new SceneObject(moved, one.material(0));
    }

    /** The scene's JSON with one object, {@code element[from, to)}: the bytes before its first object, that one, those after its last. */
    private static byte[] alone(byte[] json, int[] objects, byte[] element, int from, int to) {
        int before = objects[0], after = end(objects, objects.length / PER - 1);
        byte[] scene = new byte[before + (to - from) + (json.length - after)];
        System.arraycopy(json, 0, scene, 0, before);
        System.arraycopy(element, from, scene, before, to - from);
        System.arraycopy(json, after, scene, before + to - from, json.length - after);
        return scene;
    }

    private static int start(int[] objects, int i) {
        return objects[PER * i];
    }

    private static int end(int[] objects, int i) {
        return objects[PER * i + 1];
    }

    private void keep(PreviewRequest request, int[] objects, CompiledScene scene) {
        release();
        if (objects == null || closed
                || (objects.length / PER < MIN_OBJECTS && request.scene().length < MIN_BYTES)) {
            return;
        }
        MemoryBudget.Reservation held = memory.tryReserveYielding(
                request.scene().length + RenderMemory.sceneBytes(scene.scene()), this::release);
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

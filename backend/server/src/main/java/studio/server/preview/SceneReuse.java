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
import tools.jackson.databind.JsonNode;

/**
 * A live view's last compiled scene, kept to compile the next revision from: a drag changes one
 * object, and reading the other 9,999 again would be most of a revision's time. The next revision
 * is assembled from the kept objects and the changed ones, each changed one read in a scene of its
 * own ({@link ObjectReading}); that is the scene reading the whole revision gives, to the bit: each
 * object maps on its own (its shape and material depend on its element alone), and the engine's
 * objects are immutable. Which objects changed is told, never worked out from the scenes:
 * <ul>
 * <li>for a patch ({@link #compilePatched}), by its paths ({@link ObjectOrigins}): objects moved,
 *     added or changed, and whether anything outside the objects changed (the rest of the scene
 *     is then read with a stand-in object);
 * <li>for a whole scene ({@link #compile}), by the elements of its {@code objects} array whose
 *     bytes differ from the kept revision's, when the JSON around them is byte for byte the same.
 * </ul>
 * The same tally goes on to the kept film ({@link Revision#origins}). Anything else (another object
 * count, the view's size, a mesh scaled, turned or with another source, more than a few changed, a
 * changed element that does not read) is read in full, as {@code POST /api/render} reads it, and
 * so are its problems.
 *
 * <p>Every revision compiled is kept (so that what the next one changed can be told, for the kept
 * film too), while the render memory can hold the kept bytes and objects; the memory is given back
 * when the view closes, or when other work finds the memory short (a yielding reservation: the next
 * revision is then read in full). {@link #compile} and {@link #compilePatched} are called by the
 * view's worker, one revision at a time; {@link #close} by any thread, at once.
 */
final class SceneReuse implements AutoCloseable {

    /** More changed objects than this are read in full. */
    static final int MAX_CHANGED = 8;
    /** Ints an object takes in a request's {@code objects}. */
    private static final int PER = SceneObjectsInJson.PER_OBJECT;
    /** A three-vertex OBJ text, as a JSON string, that stands in for an unchanged mesh's while its other fields are read. */
    private static final byte[] STAND_IN = "\"v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 3\\n\"".getBytes(StandardCharsets.US_ASCII);

    /**
     * A revision's scene, and what changed since the last revision compiled.
     *
     * @param origins for each object, the index of the last revision's object it is unchanged from,
     *                or -1; null when not told (every object may have changed)
     */
    record Revision(CompiledScene compiled, int[] origins) {
    }

    /** The kept revision: its scene's bytes and its objects' ranges in them (null for a patched one), the view's size and the scene. */
    private record Kept(byte[] json, int[] objects, int width, int height, CompiledScene compiled,
                        MemoryBudget.Reservation memory) {
    }

    private final MemoryBudget memory;
    private final AtomicReference<Kept> kept = new AtomicReference<>();
    private volatile boolean closed;

    SceneReuse(MemoryBudget memory) {
        this.memory = memory;
    }

    /**
     * The scene of a whole revision: assembled from the kept one where only some objects changed,
     * else {@code read} from its whole JSON. {@code read} compiles a scene's JSON at the view's size (and
     * throws as {@code POST /api/render} would refuse it); it is also how each changed object is read.
     */
    Revision compile(PreviewRequest request, MemoryGate memory, Function<byte[], CompiledScene> read) {
        int[] objects = request.objects();
        Kept before = kept.get();
        Revision assembled = objects != null && before != null && before.json() != null
                ? fromKept(before, request, objects, memory, read) : null;
        Revision revision = assembled != null ? assembled : new Revision(read.apply(request.scene()), null);
        keep(objects != null ? request.scene() : null, objects, request, revision.compiled());
        return revision;
    }

    /**
     * The scene of a patched revision, {@code after}, patched from {@code before} (the tree of the
     * last revision compiled) with the changes {@code changes} tells: assembled from the kept scene,
     * else {@code read} whole; null {@code before} or {@code changes}: the change is not known, read whole.
     */
    Revision compilePatched(JsonNode before, JsonNode after, ObjectOrigins changes, PreviewRequest request,
                            MemoryGate memory, Function<byte[], CompiledScene> read) {
        Kept last = kept.get();
        int[] origins = changes != null && before != null ? changes.origins() : null;
        boolean reusable = last != null && origins != null && request.width() == last.width()
                && request.height() == last.height() && changes.changed() <= MAX_CHANGED
                && origins.length == last.compiled().scene().objectCount();
        CompiledScene assembled = !reusable ? null
                : changes.changed() == 0 && !changes.frameChanged() ? last.compiled() // a patch of tests alone, or none
                : fromTree(last.compiled(), before, after, origins, changes.frameChanged(), memory, read);
        CompiledScene scene = assembled != null ? assembled : read.apply(TreeObjects.bytes(after));
        keep(null, null, request, scene);
        return new Revision(scene, origins);
    }

    /**
     * The kept scene becomes {@code lit} (the same scene, its meshes given light buffers) if it is
     * still {@code compiled}, so that the next revision's unchanged meshes keep their buffers.
     */
    void lit(CompiledScene compiled, CompiledScene lit) {
        Kept last = kept.get();
        if (last != null && last.compiled() == compiled && lit != compiled) {
            kept.compareAndSet(last, new Kept(last.json(), last.objects(), last.width(), last.height(), lit,
                    last.memory()));
        }
    }

    /** Gives the kept scene's memory back; nothing is kept from now on. */
    @Override
    public void close() {
        closed = true;
        release();
    }

    private static CompiledScene fromTree(CompiledScene last, JsonNode before, JsonNode after, int[] origins,
                                          boolean frameChanged, MemoryGate memory, Function<byte[], CompiledScene> read) {
        CompiledScene frame = last;
        if (frameChanged) {
            try {
                frame = read.apply(TreeObjects.frame(after));
            } catch (RuntimeException e) {
                return null; // read in full, for the problems by their whole scene's paths
            }
        }
        Scene scene = last.scene();
        List<SceneObject> objects = new ArrayList<>(origins.length);
        for (int i = 0; i < origins.length; i++) {
            SceneObject object = origins[i] >= 0 ? new SceneObject(scene.shape(origins[i]), scene.material(origins[i]))
                    : TreeObjects.read(after, i, TreeObjects.element(before, i), scene.shape(i), memory, read);
            if (object == null) {
                return null;
            }
            objects.add(object);
        }
        return assemble(frame, scene, objects, memory);
    }

    /**
     * The scene of {@code frame} (its camera, lights and settings) with these objects, its trees
     * refitted from {@code last}'s where the objects are its own but a few ({@link Scene#reusing}).
     * A changed mesh gets the light buffers a one-sample render of the view pays for, not those of
     * the final pass: the view's first frames come before them ({@link PreviewRenderer#lit}).
     */
    private static CompiledScene assemble(CompiledScene frame, Scene last, List<SceneObject> objects, MemoryGate memory) {
        Scene scene = frame.scene();
        long oneSample = (long) frame.settings().width() * frame.settings().height();
        List<SceneObject> lit = MeshLightBuffers.forRender(objects, scene.lights(), oneSample, memory);
        return new CompiledScene(Scene.reusing(last, scene.camera(), lit, scene.lights(), scene.background(), scene.ambient()),
                frame.settings(), frame.format(), frame.quality(), frame.fileStem());
    }

    private Revision fromKept(Kept last, PreviewRequest request, int[] objects, MemoryGate memory,
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
        int[] origins = new int[n];
        int changed = 0;
        for (int i = 0; i < n; i++) {
            boolean same = Arrays.equals(json, start(objects, i), end(objects, i), was, start(wasObjects, i),
                    end(wasObjects, i));
            origins[i] = same ? i : -1;
            if (!same && ++changed > MAX_CHANGED) {
                return null;
            }
        }
        if (changed == 0) {
            return new Revision(last.compiled(), origins);
        }
        List<SceneObject> assembled = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            SceneObject object = origins[i] == i ? new SceneObject(scene.shape(i), scene.material(i))
                    : scene.shape(i) instanceof TriangleMesh mesh
                    ? movedMesh(mesh, json, objects, i, was, wasObjects, memory, read)
                    : ObjectReading.alone(alone(json, objects, json, start(objects, i), end(objects, i)), read);
            if (object == null) {
                return null;
            }
            assembled.add(object);
        }
        return new Revision(assemble(last.compiled(), scene, assembled, memory), origins);
    }

    /**
     * An inline mesh whose OBJ text is the kept one's, byte for byte, while something else of it
     * changed: read with a three-vertex stand-in for the text (so 3.4 MB of OBJ are neither decoded
     * nor digested again), and moved if only its position or material changed
     * ({@link ObjectReading#movedMesh}). Null for anything else.
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
        return ObjectReading.movedMesh(kept, alone(json, objects, element, 0, element.length), memory, read);
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

    /** Keeps a compiled revision ({@code json} and {@code objects}: its bytes and their objects, or null). */
    private void keep(byte[] json, int[] objects, PreviewRequest request, CompiledScene scene) {
        release();
        if (closed) {
            return;
        }
        MemoryBudget.Reservation held = memory.tryReserveYielding(
                (json != null ? json.length : 0) + RenderMemory.sceneBytes(scene.scene()), this::release);
        if (held != null) {
            kept.set(new Kept(json, objects, request.width(), request.height(), scene, held));
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

package studio.server.preview;

import java.util.function.Function;

import studio.engine.geometry.TriangleMesh;
import studio.engine.memory.MemoryGate;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;
import studio.server.scene.compiling.CompiledScene;

/**
 * One changed object of a live view's revision, read in a scene of its own (the revision's scene
 * with that one object), as {@link SceneReuse} assembles a scene from the kept objects and the
 * changed ones. Null wherever the object must be read with the whole scene instead: it does not
 * read (its problems are named by the whole scene's paths), or it is a mesh other than a kept one
 * moved (meshes share one triangle limit).
 */
final class ObjectReading {

    /** A three-vertex OBJ text that stands in for an unchanged mesh's while its other fields are read. */
    static final String STAND_IN = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

    private ObjectReading() {
    }

    /** The one object of {@code alone}; null if it does not read or is a mesh. */
    static SceneObject alone(byte[] alone, Function<byte[], CompiledScene> read) {
        Scene one = readOne(alone, read);
        if (one == null || one.shape(0) instanceof TriangleMesh) {
            return null;
        }
        return new SceneObject(one.shape(0), one.material(0));
    }

    /**
     * A kept mesh where {@code alone} (its element, with {@link #STAND_IN} for its unchanged
     * source) puts it: the kept mesh moved there ({@link TriangleMesh#movedTo}: the very mesh
     * reading it in full builds), if only its position or material changed; else null.
     */
    static SceneObject movedMesh(TriangleMesh kept, byte[] alone, MemoryGate memory, Function<byte[], CompiledScene> read) {
        Scene one = readOne(alone, read);
        if (one == null || !(one.shape(0) instanceof TriangleMesh placed) || placed.scale() != kept.scale()
                || !placed.rotationDegrees().equals(kept.rotationDegrees())) {
            return null;
        }
        TriangleMesh moved = placed.position().equals(kept.position()) ? kept : kept.movedTo(placed.position(), memory);
        return new SceneObject(moved, one.material(0));
    }

    private static Scene readOne(byte[] alone, Function<byte[], CompiledScene> read) {
        CompiledScene compiled;
        try {
            compiled = read.apply(alone);
        } catch (RuntimeException e) {
            return null; // read in full, for the problems by their whole scene's paths
        }
        Scene one = compiled.scene();
        return one.objectCount() == 1 ? one : null;
    }
}

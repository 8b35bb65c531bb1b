package studio.server.render;

import studio.engine.geometry.TriangleMesh;
import studio.engine.scene.Scene;
import studio.server.scene.compiling.CompiledScene;

/**
 * How much heap a render holds, estimated before it starts (see {@link studio.server.system.MemoryBudget}).
 * The figures are upper bounds of what the engine and the encoders allocate:
 * <ul>
 * <li>per pixel {@value #BYTES_PER_PIXEL}: the film (three doubles, 24), the 8-bit image (4), the
 *     encoding (a PNG's filtered rows and compressed pieces, then the file with its growing buffer:
 *     up to 12), a job's tile previews until it ends (4) and,
 *     under adaptive sampling, the base samples on the tiles' edges (22 with 32-pixel tiles: a ring
 *     of {@code TileBorders.LINES} = 2 pixels, 88 bytes each, a quarter of the pixels; the 16-pixel
 *     tiles of small images take more, within the fixed part);</li>
 * <li>per triangle {@value #BYTES_PER_TRIANGLE}: positions, normals and indices, the mesh's BVH and
 *     the build's temporary boxes (about 160 measured on a million-triangle mesh);</li>
 * <li>per object {@value #BYTES_PER_OBJECT}: the shape, its material and its place in the scene's BVH;</li>
 * <li>{@value #FIXED_BYTES} for the workers' buffers and the rest.</li>
 * </ul>
 */
public final class RenderMemory {

    static final long BYTES_PER_PIXEL = 66;
    static final long BYTES_PER_TRIANGLE = 200;
    static final long BYTES_PER_OBJECT = 400;
    static final long FIXED_BYTES = 4L << 20;

    private RenderMemory() {
    }

    public static long estimate(CompiledScene compiled) {
        long pixels = (long) compiled.settings().width() * compiled.settings().height();
        return FIXED_BYTES + pixels * BYTES_PER_PIXEL + sceneBytes(compiled.scene());
    }

    /** What the scene itself holds: its objects and its meshes' triangles (the film and buffers aside). */
    public static long sceneBytes(Scene scene) {
        long triangles = 0;
        for (int i = 0; i < scene.objectCount(); i++) {
            if (scene.shape(i) instanceof TriangleMesh mesh) {
                triangles += mesh.triangleCount();
            }
        }
        return triangles * BYTES_PER_TRIANGLE + scene.objectCount() * BYTES_PER_OBJECT;
    }

    /** Bytes as MiB for messages, rounded up. */
    public static long mebibytes(long bytes) {
        return (bytes + (1L << 20) - 1) >> 20;
    }
}

package studio.server.scene.compiling;

import java.util.Map;
import java.util.Objects;

import studio.engine.memory.MemoryGate;

/**
 * A scene to read, check and map onto the engine: its JSON and how to read it. Callers differ by
 * data, not by overloads: {@link #of} reads the JSON as it is, for all cores, with the compiler's
 * own mesh files and no memory limit, and the withers change one part.
 *
 * @param overrides values to set before validation, by path ({@code "image.width" -> 320})
 * @param threads   worker threads for the render, 0 for all cores
 * @param files     where meshes' files are read (e.g. the scene file's folder); null: the compiler's own
 * @param memory    asked before the engine's objects and the meshes' arrays are allocated (the body's
 *                  own parse is reckoned as it arrives, before the compiler is called)
 */
public record CompileRequest(byte[] json, Map<String, Object> overrides, int threads, MeshFiles files,
                             MemoryGate memory) {

    public CompileRequest {
        Objects.requireNonNull(json, "json");
        Objects.requireNonNull(overrides, "overrides");
        Objects.requireNonNull(memory, "memory");
    }

    public static CompileRequest of(byte[] json) {
        return new CompileRequest(json, Map.of(), 0, null, MemoryGate.UNLIMITED);
    }

    public CompileRequest overriding(Map<String, Object> values) {
        return new CompileRequest(json, values, threads, files, memory);
    }

    public CompileRequest onThreads(int count) {
        return new CompileRequest(json, overrides, count, files, memory);
    }

    public CompileRequest readingMeshesFrom(MeshFiles from) {
        return new CompileRequest(json, overrides, threads, from, memory);
    }

    public CompileRequest within(MemoryGate gate) {
        return new CompileRequest(json, overrides, threads, files, gate);
    }
}

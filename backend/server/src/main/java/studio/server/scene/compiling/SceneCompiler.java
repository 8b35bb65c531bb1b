package studio.server.scene.compiling;

import java.util.Map;
import java.util.function.Supplier;

import jakarta.validation.Validator;

import studio.engine.memory.MemoryGate;
import studio.server.scene.format.InvalidSceneException;
import studio.server.scene.format.SceneLimits;
import studio.server.scene.reading.LazyValidation;
import studio.server.scene.reading.SceneReader;

/** Scene JSON in, an engine scene out: the one path the API and the CLI share. */
public final class SceneCompiler {

    private final SceneReader reader;
    private final SceneMapper mapper;
    private final MeshFiles meshFiles;

    /** @param meshFiles where meshes' {@code file} names are read from, unless a call says otherwise */
    public SceneCompiler(SceneReader reader, SceneMapper mapper, MeshFiles meshFiles) {
        this.reader = reader;
        this.mapper = mapper;
        this.meshFiles = meshFiles;
    }

    /** Inline meshes only. */
    public SceneCompiler(SceneReader reader, SceneMapper mapper) {
        this(reader, mapper, MeshFiles.none());
    }

    /**
     * @param overrides values to set before validation, by path ({@code "image.width" -> 320})
     * @param threads   worker threads for the render, 0 for all cores
     * @throws InvalidSceneException listing every problem, before anything is rendered
     */
    public CompiledScene compile(byte[] json, Map<String, Object> overrides, int threads) {
        return compile(json, overrides, threads, meshFiles);
    }

    /** As above, reading meshes' files from {@code files} (e.g. the scene file's folder). */
    public CompiledScene compile(byte[] json, Map<String, Object> overrides, int threads, MeshFiles files) {
        return compile(json, overrides, threads, files, MemoryGate.UNLIMITED);
    }

    /**
     * As above, asking {@code memory} before the engine's objects and the meshes' arrays are
     * allocated (the body's own parse is reckoned as it arrives, before this is called).
     */
    public CompiledScene compile(byte[] json, Map<String, Object> overrides, int threads, MeshFiles files,
                                 MemoryGate memory) {
        return mapper.map(reader.read(json, overrides), threads, files, memory);
    }

    /** As {@link #compile(byte[])}, asking {@code memory} before the engine allocates. */
    public CompiledScene compile(byte[] json, MemoryGate memory) {
        return compile(json, Map.of(), 0, meshFiles, memory);
    }

    /** As {@link #compile(byte[], Map, int)}, asking {@code memory} before the engine allocates. */
    public CompiledScene compile(byte[] json, Map<String, Object> overrides, int threads, MemoryGate memory) {
        return compile(json, overrides, threads, meshFiles, memory);
    }

    /**
     * A compiler outside Spring (the CLI, the benchmark, tests) with this server's default limits,
     * reading as a process that reads one scene does ({@link SceneReader#forOneScene}); the caller
     * owns the validator (e.g. a {@link LazyValidation}) and closes it.
     */
    public static SceneCompiler standalone(Supplier<Validator> validator) {
        return standalone(validator, MeshFiles.none());
    }

    /** As {@link #standalone(Supplier)}, reading meshes' files from {@code meshFiles}. */
    public static SceneCompiler standalone(Supplier<Validator> validator, MeshFiles meshFiles) {
        return new SceneCompiler(SceneReader.forOneScene(validator), new SceneMapper(SceneLimits.DEFAULTS), meshFiles);
    }

    public CompiledScene compile(byte[] json) {
        return compile(json, Map.of(), 0);
    }
}

package studio.server.scene.compiling;

import java.util.function.Supplier;

import jakarta.validation.Validator;

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
     * Reads, checks and maps the scene the request holds.
     *
     * @throws InvalidSceneException listing every problem, before anything is rendered
     */
    public CompiledScene compile(CompileRequest request) {
        MeshFiles files = request.files() != null ? request.files() : meshFiles;
        return mapper.map(reader.read(request.json(), request.overrides()), request.threads(), files, request.memory());
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
}

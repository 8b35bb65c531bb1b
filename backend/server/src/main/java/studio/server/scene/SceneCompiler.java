package studio.server.scene;

import java.util.Map;

import jakarta.validation.ValidatorFactory;

/** Scene JSON in, an engine scene out: the one path the API and the CLI share. */
public final class SceneCompiler {

    private final SceneReader reader;
    private final SceneMapper mapper;

    public SceneCompiler(SceneReader reader, SceneMapper mapper) {
        this.reader = reader;
        this.mapper = mapper;
    }

    /**
     * @param overrides values to set before validation, by path ({@code "image.width" -> 320})
     * @param threads   worker threads for the render, 0 for all cores
     * @throws InvalidSceneException listing every problem, before anything is rendered
     */
    public CompiledScene compile(byte[] json, Map<String, Object> overrides, int threads) {
        return mapper.map(reader.read(json, overrides), threads);
    }

    /**
     * A compiler outside Spring (the CLI, the benchmark, tests) with this server's default limits;
     * the caller owns the validator factory and closes it.
     */
    public static SceneCompiler standalone(ValidatorFactory validation) {
        return new SceneCompiler(new SceneReader(validation.getValidator()), new SceneMapper(SceneLimits.DEFAULTS));
    }

    public CompiledScene compile(byte[] json) {
        return compile(json, Map.of(), 0);
    }
}

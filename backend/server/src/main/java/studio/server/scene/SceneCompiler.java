package studio.server.scene;

import java.util.Map;

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

    public CompiledScene compile(byte[] json) {
        return compile(json, Map.of(), 0);
    }
}

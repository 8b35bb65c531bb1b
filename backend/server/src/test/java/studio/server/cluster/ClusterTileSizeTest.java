package studio.server.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.util.List;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import studio.server.scene.compiling.CompileRequest;
import studio.engine.render.Film;
import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.engine.render.TileRect;
import studio.engine.render.TileRenderer;
import studio.engine.render.TileRequest;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.examples.ExampleSceneFiles;

/**
 * The cluster cuts a large image into tiles of {@link ClusterJobs#LARGE_TILE} pixels, twice the
 * engine's own, and its top rows into tiles twice as large again ({@link ClusterTiling}): a worker
 * renders any such tile, with every sampler, adaptive or not, to exactly the pixels one machine's
 * render gives. (The adaptive Sobol sampling's buffers once held a 32-pixel
 * tile only: every cluster job of a large image with the default sampler failed at its first tile.)
 */
class ClusterTileSizeTest {

    private static CompiledScene scene(String render) {
        String json = """
                {"image": {"width": 150, "height": 330},
                 "render": %s,
                 "lights": [{"type": "point", "position": [3, 5, 4]}],
                 "objects": [{"type": "sphere", "center": [0, 1, 0], "material": {"type": "glass"}},
                             {"type": "box", "center": [1.6, 0.5, 0], "size": [1, 1, 1], "rotation": [0, 30, 0]},
                             {"type": "plane"}]}
                """.formatted(render);
        return ExampleSceneFiles.compiler().compile(CompileRequest.of(json.getBytes(StandardCharsets.UTF_8)));
    }

    @ParameterizedTest
    @ValueSource(strings = {"{\"samples\": 16}", "{\"sampler\": \"sobol\", \"samples\": 16, \"adaptive\": 0.02}",
            "{\"sampler\": \"jittered\", \"samples\": 16}", "{\"sampler\": \"jittered\", \"samples\": 16, \"adaptive\": 0.02}",
            "{\"sampler\": \"multijittered\", \"samples\": 9, \"adaptive\": 0}", "{\"sampler\": \"regular\", \"samples\": 4}"})
    void largeTilesRenderOneMachinesPixels(String render) {
        CompiledScene scene = scene(render);
        int width = scene.settings().width(), height = scene.settings().height();
        Film oneMachine = Renderer.render(RenderRequest.of(scene.scene(), scene.settings())).film();
        TileRenderer worker = new TileRenderer(scene.scene(), scene.settings());
        List<TileRect> tiles = ClusterTiling.tiles(width, height, ClusterJobs.LARGE_TILE);
        assertThat(tiles).as("large and small tiles").anyMatch(tile -> tile.width() == 2 * ClusterJobs.LARGE_TILE)
                .anyMatch(tile -> tile.width() == ClusterJobs.LARGE_TILE);
        for (TileRect tile : tiles) {
            Film film = Film.ofTile(tile);
            worker.render(TileRequest.whole(film, tile));
            for (int y = tile.y(); y < tile.y() + tile.height(); y++) {
                for (int x = tile.x(); x < tile.x() + tile.width(); x++) {
                    for (int c = 0; c < 3; c++) {
                        assertThat(film.get(x, y, c)).as("pixel %d,%d channel %d", x, y, c)
                                .isEqualTo(oneMachine.get(x, y, c));
                    }
                }
            }
        }
    }
}

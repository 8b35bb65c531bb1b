package studio.server.preview;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.Map;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;

import studio.engine.render.Film;
import studio.server.render.RenderBudget;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.reading.LazyValidation;
import tools.jackson.databind.json.JsonMapper;

/** A live view's pass renders into the film it is given, allocating none of the view's size besides. */
class PreviewRendererTest {

    private static final int WIDTH = 640, HEIGHT = 480;
    private static final LazyValidation VALIDATION = new LazyValidation();
    private static final SceneCompiler COMPILER = SceneCompiler.standalone(VALIDATION);

    @AfterAll
    static void close() {
        VALIDATION.close();
    }

    @Test
    void aCoarsePassAllocatesNoFilmOfItsOwn() {
        PreviewRenderer renderer = new PreviewRenderer(COMPILER, RenderBudget.unlimited(), 1,
                new PreviewProperties(16, 2048, 2048, Duration.ofMinutes(10)), JsonMapper.builder().build());
        CompiledScene scene = COMPILER.compile(CompileRequest.of(("{\"render\": {\"samples\": 4},"
                        + "\"lights\": [{\"type\": \"point\", \"position\": [4, 7, 5]}],"
                        + "\"objects\": [{\"type\": \"sphere\", \"center\": [0, 1, 0], \"radius\": 1}, {\"type\": \"plane\"}]}")
                        .getBytes(StandardCharsets.UTF_8))
                .overriding(Map.of("image.width", WIDTH, "image.height", HEIGHT)).onThreads(1));
        PreviewPass coarsest = PreviewPass.plan(scene.settings()).get(0);
        Film film = new Film(WIDTH, HEIGHT);
        var threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long filmBytes = 3L * 8 * WIDTH * HEIGHT;
        long least = Long.MAX_VALUE;
        for (int i = 0; i < 3; i++) { // the least of a few: the first pays for classes loaded on the way
            long before = threads.getCurrentThreadAllocatedBytes();
            byte[] frame = renderer.render(scene, coarsest, film, null, 1, System.nanoTime(), () -> false);
            least = Math.min(least, threads.getCurrentThreadAllocatedBytes() - before);
            assertThat(frame.length).isGreaterThan(4);
        }
        assertThat(least).as("bytes a 1/64 pass allocates on the view's thread").isLessThan(filmBytes / 8);
        double onLattice = 0, off = 0;
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                double value = film.get(x, y, 0) + film.get(x, y, 1) + film.get(x, y, 2);
                if (x % 8 == 4 && y % 8 == 4) {
                    onLattice += value;
                } else {
                    off += value;
                }
            }
        }
        assertThat(onLattice).as("the pass rendered into the film given").isPositive();
        assertThat(off).as("and only its lattice's pixels").isZero();
    }
}

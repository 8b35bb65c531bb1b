package studio.server.render;

import java.io.IOException;
import java.io.InputStream;
import java.time.Duration;
import java.util.Arrays;
import java.util.Comparator;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.springframework.beans.factory.SmartInitializingSingleton;
import org.springframework.core.io.Resource;
import org.springframework.core.io.support.PathMatchingResourcePatternResolver;

import studio.engine.render.RenderCancelledException;
import studio.engine.render.RenderResult;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.MeshFiles;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.system.MemoryBudget;

/**
 * Renders the jar's training scenes ({@code bin/training}: 160x120, one of each kind the engine
 * treats apart) once at start-up, before the port opens, through the same reading, engine and
 * encoder as a request, its render memory reserved first, so that a fresh service's first job runs
 * compiled code rather than paying the JIT on a user's time (docs/cluster.md, the pinned ratio cold
 * and warm). Bounded by {@code studio.warm-up}; a failure is logged and start-up goes on.
 */
final class RenderWarmUp implements SmartInitializingSingleton {

    private static final Logger log = LoggerFactory.getLogger(RenderWarmUp.class);
    static final String SCENES = "classpath*:training/*.json";

    /** What the warm-up did: scenes rendered to the end, of how many, in how long. */
    record Outcome(int rendered, int scenes, long elapsedMillis) {
    }

    private final SceneCompiler compiler;
    private final RenderBudget budget;
    private final int threads;
    private final Duration limit;

    RenderWarmUp(SceneCompiler compiler, RenderBudget budget, int threads, Duration limit) {
        this.compiler = compiler;
        this.budget = budget;
        this.threads = threads;
        this.limit = limit;
    }

    @Override
    public void afterSingletonsInstantiated() {
        if (limit.isZero() || limit.isNegative()) {
            return;
        }
        Outcome outcome = run();
        log.info("Warmed up the render path in {} ms: {} of {} training scenes rendered (studio.warm-up={}, 0s turns "
                + "it off)", outcome.elapsedMillis(), outcome.rendered(), outcome.scenes(), limit.toMillis() + "ms");
    }

    /** Renders each training scene in name order until they are done or the limit has passed. */
    Outcome run() {
        long start = System.nanoTime();
        long deadline = start + limit.toNanos();
        Resource[] scenes = scenes();
        int rendered = 0;
        for (Resource scene : scenes) {
            if (System.nanoTime() - deadline > 0) {
                break;
            }
            try {
                rendered += render(read(scene), deadline) ? 1 : 0;
            } catch (RenderCancelledException e) {
                break;
            } catch (RuntimeException e) {
                log.warn("The warm-up could not render {}: {}", scene.getFilename(), e.getMessage());
            }
        }
        return new Outcome(rendered, scenes.length, (System.nanoTime() - start) / 1_000_000);
    }

    /** Renders one scene within the render memory, as a request would; false if the memory is taken. */
    private boolean render(byte[] json, long deadline) {
        CompiledScene compiled = compiler.compile(CompileRequest.of(json).onThreads(threads)
                .readingMeshesFrom(MeshFiles.onClasspath("training/")));
        try (MemoryBudget.Reservation memory = budget.reserve(compiled)) {
            if (memory == null) {
                return false;
            }
            RenderResult result = budget.render(compiled.request().cancelledWhen(() -> System.nanoTime() - deadline > 0));
            ImageFiles.encode(result.film(), compiled.format(), compiled.quality());
            return true;
        }
    }

    private static Resource[] scenes() {
        try {
            Resource[] found = new PathMatchingResourcePatternResolver(RenderWarmUp.class.getClassLoader())
                    .getResources(SCENES);
            Arrays.sort(found, Comparator.comparing(Resource::getFilename));
            return found;
        } catch (IOException e) {
            log.warn("The warm-up found no training scenes: {}", e.getMessage());
            return new Resource[0];
        }
    }

    private static byte[] read(Resource scene) {
        try (InputStream in = scene.getInputStream()) {
            return in.readAllBytes();
        } catch (IOException e) {
            throw new IllegalStateException("cannot read " + scene.getFilename() + ": " + e.getMessage(), e);
        }
    }
}

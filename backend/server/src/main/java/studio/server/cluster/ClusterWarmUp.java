package studio.server.cluster;

import java.io.IOException;
import java.io.InputStream;
import java.time.Duration;
import java.util.HashSet;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.springframework.beans.factory.SmartInitializingSingleton;

import studio.engine.render.RenderCancelledException;
import studio.engine.render.RenderResult;
import studio.server.job.JobState;
import studio.server.job.JobStatus;
import studio.server.job.TileEvent;
import studio.server.job.TilePng;
import studio.server.render.ImageFiles;
import studio.server.render.RenderMemory;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.system.MemoryBudget;

/**
 * Renders a tiny scene's tiles through this member's own cluster path at start-up, before the port
 * opens: the queue, the claims, the results and their listener, the assembly, each tile's PNG event
 * in an event log, the job table's compare-and-set, the image, all sealed, with the code a job runs
 * ({@link TileFarm}, {@link TileWorkers}, {@link JobPublisher}), so that a fresh member's first job
 * runs Hazelcast's and the tile path's code compiled instead of paying the JIT on a user's time (the
 * compiler threads' CPU during two pinned members' first job, docs/cluster.md, "Where two members'
 * CPU goes"). Its structures are named for this member ({@link ClusterData#named}): no other
 * member's workers take its tiles, they hold no data of a job, and they are destroyed at the end;
 * partitions of them live on the other members, so their network path is compiled too. Bounded by
 * {@code studio.cluster.warm-up} (by default {@code studio.warm-up}, the render warm-up's limit); a
 * failure is logged and start-up goes on.
 */
final class ClusterWarmUp implements SmartInitializingSingleton {

    private static final Logger log = LoggerFactory.getLogger(ClusterWarmUp.class);
    static final String SCENE = "cluster/warm-up.json";
    /** 6-pixel tiles of the 128x128 scene ({@link ClusterTiling}: 12-pixel ones first): 253 tiles a round, each a few round trips and hardly a render. */
    static final int TILE_SIZE = 6;
    /** Past the 200 calls after which the JIT compiles a method with C1's profile, for code called once a tile. */
    static final int ROUNDS = 2;
    /** A round's job id, before its number. */
    private static final String ID = "warm-up-";

    /** What the warm-up did: tiles sent through the cluster in rounds that ended, in how long. */
    record Outcome(int tiles, int rounds, long elapsedMillis) {
    }

    private final ClusterData data;
    private final SceneCompiler compiler;
    private final MemoryBudget memory;
    private final Duration limit;

    ClusterWarmUp(ClusterData data, SceneCompiler compiler, MemoryBudget memory, Duration limit) {
        this.data = data;
        this.compiler = compiler;
        this.memory = memory;
        this.limit = limit;
    }

    @Override
    public void afterSingletonsInstantiated() {
        if (limit.isZero() || limit.isNegative()) {
            return;
        }
        try {
            Outcome outcome = run();
            log.info("Warmed up the cluster path in {} ms: {} tiles in {} of {} rounds through this member's own "
                    + "structures (studio.cluster.warm-up={}, 0s turns it off)", outcome.elapsedMillis(),
                    outcome.tiles(), outcome.rounds(), ROUNDS, limit.toMillis() + "ms");
        } catch (RuntimeException e) {
            log.warn("The cluster warm-up stopped: {}", e.toString());
        }
    }

    /**
     * Renders the scene {@value #ROUNDS} times through the cluster, or until the limit has passed; none
     * while other work holds the render memory it reserves first, as a request does.
     */
    Outcome run() {
        long start = System.nanoTime();
        long deadline = start + limit.toNanos();
        String memberId = data.member().getCluster().getLocalMember().getUuid().toString();
        ClusterData own = data.named("studio-warm-up-" + memberId + "-");
        CompiledScene scene = compiler.compile(CompileRequest.of(read()));
        try (MemoryBudget.Reservation held = memory.tryReserve(RenderMemory.estimate(scene))) {
            if (held == null) { // other work holds the render memory: it goes first
                return new Outcome(0, 0, (System.nanoTime() - start) / 1_000_000);
            }
            return run(own, memberId, scene, start, deadline);
        }
    }

    /** The rounds, their render memory reserved. */
    private Outcome run(ClusterData own, String memberId, CompiledScene scene, long start, long deadline) {
        int tiles = 0, rounds = 0;
        TileWorkers workers = new TileWorkers(own, new JobScenes(own.scenes(), compiler, memory), 1);
        TileFarm farm = new TileFarm(own, workers, id -> false);
        workers.start();
        try {
            for (int round = 0; round < ROUNDS; round++) {
                String id = ID + round;
                try {
                    tiles += render(own, farm, id, memberId, scene, deadline);
                    rounds++;
                } catch (RenderCancelledException e) {
                    break;
                } finally {
                    own.events(id).destroy();
                }
            }
        } finally {
            workers.close();
            // a worker's last result may have come after its round's maps were destroyed: the round's maps go again
            for (int round = 0; round < ROUNDS; round++) {
                own.tiles(ID + round).destroy();
                own.claims(ID + round).destroy();
            }
            own.queue().destroy();
            own.jobs().destroy();
            own.images().destroy();
            own.scenes().destroy();
        }
        return new Outcome(tiles, rounds, (System.nanoTime() - start) / 1_000_000);
    }

    /** One round: the scene as a job of this member, its tiles rendered by its own workers; the tiles it rendered. */
    private static int render(ClusterData own, TileFarm farm, String id, String memberId, CompiledScene scene,
                              long deadline) {
        int width = scene.settings().width(), height = scene.settings().height();
        JobStatus running = new JobStatus(id, JobState.RUNNING, 0, 0, null, width, height, "warm-up.png", "image/png",
                null, null);
        own.jobs().set(id, new JobRecord(running, memberId, TILE_SIZE, ""));
        JobPublisher publisher = new JobPublisher(id, memberId, own.jobs(), own.images(), own.events(id),
                () -> running, () -> null, new HashSet<>(), () -> false);
        RenderResult result = farm.render(id, scene, TILE_SIZE, false, (film, tile, done, total) ->
                        publisher.tile(new TileEvent(tile.x(), tile.y(), tile.width(), tile.height(),
                                TilePng.encode(film, tile), (double) done / total)),
                () -> System.nanoTime() - deadline > 0);
        byte[] image = ImageFiles.encode(result.film(), scene.format(), scene.quality());
        JobStatus done = new JobStatus(id, JobState.DONE, 1, 0, null, width, height, "warm-up.png", "image/png", null,
                farm.workers(id));
        own.images().set(id, image);
        publisher.end(done);
        farm.forget(id);
        return ClusterTiling.tiles(width, height, TILE_SIZE).size();
    }

    private static byte[] read() {
        try (InputStream in = ClusterWarmUp.class.getClassLoader().getResourceAsStream(SCENE)) {
            if (in == null) {
                throw new IllegalStateException("no " + SCENE + " in the jar");
            }
            return in.readAllBytes();
        } catch (IOException e) {
            throw new IllegalStateException("cannot read " + SCENE + ": " + e.getMessage(), e);
        }
    }
}

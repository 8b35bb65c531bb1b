package studio.server.cluster;

import java.io.IOException;
import java.io.InputStream;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Map;

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
 * Renders a small scene's tiles through this member's own cluster path at start-up, before the port
 * opens, once in a job's own tile sizes (results as large as a job's) and then in many small tiles (a
 * job's round trips, many times over): the queue, the claims, the results and their listener, the
 * assembly, each tile's PNG event in an event log, the job table's compare-and-set, the image, all
 * sealed, with the code a job runs ({@link TileFarm}, {@link TileWorkers}, {@link JobPublisher}), so
 * that a fresh member's first job runs the tile path's code compiled instead of paying
 * the JIT on a user's time (the compiler threads' CPU during two pinned members' first job,
 * docs/cluster.md, "Where two members' CPU goes"). Its structures are named for this member ({@link ClusterData#named}): no other
 * member's workers take its tiles, they hold no data of a job, and they are destroyed at the end;
 * partitions of them live on the other members, so their network path is compiled too. Bounded by
 * {@code studio.cluster.warm-up} (by default {@code studio.warm-up}, the render warm-up's limit); a
 * failure is logged and start-up goes on.
 */
final class ClusterWarmUp implements SmartInitializingSingleton {

    private static final Logger log = LoggerFactory.getLogger(ClusterWarmUp.class);
    static final String SCENE = "cluster/warm-up.json";
    /**
     * 6-pixel tiles of the 128x128 scene ({@link ClusterTiling}: 12-pixel ones first): 253 tiles a small
     * round, each a few round trips and hardly a render.
     */
    static final int TILE_SIZE = 6;
    /**
     * Rounds of small tiles: 253 tiles a round, several operations each, so that more of the tile path's
     * code is compiled here rather than in a user's first job: with two rounds a pinned pair's first job
     * cost 0.45 s more CPU (docs/cluster.md, "The warm job's compiles"). Hazelcast's own code needs no
     * rounds for C2: C1 alone compiles it ({@link HazelcastCompiles}).
     */
    static final int ROUNDS = 8;
    /**
     * The first round's image side: the scene at {@value}x{@value}, cut at the cluster's own tile size
     * ({@link ClusterJobs#LARGE_TILE}) into a job's 128- and 64-pixel tiles, whose results (up to 393 KB)
     * take the network's paths for packets larger than a socket's buffer, as a real job's do.
     */
    static final int FULL_SIZE = 512;
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
                    outcome.tiles(), outcome.rounds(), ROUNDS + 1, limit.toMillis() + "ms");
        } catch (RuntimeException e) {
            log.warn("The cluster warm-up stopped: {}", e.toString());
        }
    }

    /**
     * Renders the scene once at its full size in a job's tiles and {@value #ROUNDS} times in small
     * tiles, through the cluster, or until the limit has passed; none while other work holds the render
     * memory it reserves first, as a request does.
     */
    Outcome run() {
        long start = System.nanoTime();
        long deadline = start + limit.toNanos();
        String memberId = data.member().getCluster().getLocalMember().getUuid().toString();
        ClusterData own = data.named("studio-warm-up-" + memberId + "-");
        byte[] json = read();
        CompiledScene small = compiler.compile(CompileRequest.of(json));
        CompiledScene full = compiler.compile(CompileRequest.of(json)
                .overriding(Map.of("image.width", FULL_SIZE, "image.height", FULL_SIZE)));
        try (MemoryBudget.Reservation held = memory.tryReserve(RenderMemory.estimate(full))) {
            if (held == null) { // other work holds the render memory: it goes first
                return new Outcome(0, 0, (System.nanoTime() - start) / 1_000_000);
            }
            List<Round> rounds = new ArrayList<>(List.of(new Round(full, ClusterJobs.LARGE_TILE)));
            rounds.addAll(Collections.nCopies(ROUNDS, new Round(small, TILE_SIZE)));
            return run(own, memberId, rounds, start, deadline);
        }
    }

    /** A round's scene and the tile size it is cut at. */
    record Round(CompiledScene scene, int tileSize) {
    }

    /** The rounds, their render memory reserved. */
    private Outcome run(ClusterData own, String memberId, List<Round> rounds, long start, long deadline) {
        int tiles = 0, done = 0;
        TileWorkers workers = new TileWorkers(own, new JobScenes(own.scenes(), compiler, memory), 1);
        TileFarm farm = new TileFarm(own, workers, id -> false);
        workers.start();
        try {
            for (Round round : rounds) {
                String id = ID + done;
                try {
                    tiles += render(own, farm, id, memberId, round, deadline);
                    done++;
                } catch (RenderCancelledException e) {
                    break;
                } finally {
                    own.events(id).destroy();
                }
            }
        } finally {
            workers.close();
            // a worker's last result may have come after its round's maps were destroyed: the round's maps go again
            for (int round = 0; round <= done && round < rounds.size(); round++) {
                own.tiles(ID + round).destroy();
                own.claims(ID + round).destroy();
            }
            own.queue().destroy();
            own.jobs().destroy();
            own.images().destroy();
            own.scenes().destroy();
        }
        return new Outcome(tiles, done, (System.nanoTime() - start) / 1_000_000);
    }

    /** One round: the scene as a job of this member, its tiles rendered by its own workers; the tiles it rendered. */
    private static int render(ClusterData own, TileFarm farm, String id, String memberId, Round round,
                              long deadline) {
        CompiledScene scene = round.scene();
        int width = scene.settings().width(), height = scene.settings().height();
        JobStatus running = new JobStatus(id, JobState.RUNNING, 0, 0, null, width, height, "warm-up.png", "image/png",
                null, null);
        own.jobs().set(id, new JobRecord(running, memberId, round.tileSize(), ""));
        JobPublisher publisher = new JobPublisher(id, memberId, own.jobs(), own.images(), own.events(id),
                () -> running, () -> null, new HashSet<>(), () -> false);
        RenderResult result = farm.render(id, scene, round.tileSize(), false, (film, tile, done, total) ->
                        publisher.tile(new TileEvent(tile.x(), tile.y(), tile.width(), tile.height(),
                                TilePng.encode(film, tile), (double) done / total)),
                () -> System.nanoTime() - deadline > 0);
        byte[] image = ImageFiles.encode(result.film(), scene.format(), scene.quality());
        JobStatus done = new JobStatus(id, JobState.DONE, 1, 0, null, width, height, "warm-up.png", "image/png", null,
                farm.workers(id));
        own.images().set(id, image);
        publisher.end(done);
        farm.forget(id);
        return ClusterTiling.tiles(width, height, round.tileSize()).size();
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

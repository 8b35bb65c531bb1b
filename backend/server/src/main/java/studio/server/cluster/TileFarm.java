package studio.server.cluster;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.Collection;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.function.Predicate;

import com.hazelcast.cluster.Member;

import studio.engine.render.Film;
import studio.engine.render.RenderCancelledException;
import studio.engine.render.RenderListener;
import studio.engine.render.RenderResult;
import studio.engine.render.TileRect;
import studio.server.job.JobFailedException;
import studio.server.scene.compiling.CompiledScene;

/**
 * The coordinator of a job's render in the cluster, on the member that runs the job: queues the
 * job's tiles as tasks for every member's {@link TileWorkers}, assembles the results into the film
 * as they arrive (each tile once, reported to the job's listener), and queues again the tiles whose
 * worker died (their {@link TileClaim} names a member that left), failed, or were lost, at most
 * {@value #MAX_ATTEMPTS} times per tile; then the job fails, naming the tile. A member that takes
 * the job over runs the same loop: the tiles already in the job's tile map are assembled first,
 * and only the tiles neither done, queued, nor claimed by a live member are queued again.
 *
 * <p>What is done is the coordinator's own record (the results it assembled); every other tile is
 * queued, claimed, or for a moment in no state (a worker took it and has not claimed it yet). A
 * tile in no state at two looks a second apart was lost (its worker died between taking and
 * claiming it, or its result's put failed) and is queued again, so no tile can fall out of every
 * state for good.
 */
final class TileFarm {

    private static final org.slf4j.Logger log = org.slf4j.LoggerFactory.getLogger(TileFarm.class);

    /** A tile that failed or was lost with its member this often fails its job. */
    static final int MAX_ATTEMPTS = 3;
    /** The coordinator looks for results this often, and for the cancel and the deadline. */
    static final long POLL_MILLIS = 100;
    /**
     * The coordinator looks whether a member left this often (and at once when one leaves; then it reads
     * the claims, {@link LostCheck}), and looks again this soon at tiles it found in no state.
     */
    static final long LOST_CHECK_MILLIS = 1_000;
    /**
     * The coordinator looks for tiles in no state this often (a second after a member left): it reads
     * the queue, the claims, and the results of such tiles (map events are not delivered reliably
     * while partitions move after a member died). A lost tile costs at most this long and a second.
     */
    static final long MISSING_CHECK_MILLIS = 5_000;

    private final ClusterData data;
    private final TileWorkers workers;
    private final SealedQueue<TileTask> queue;
    private final Predicate<String> kept;
    /** The tiles each member rendered, per job of this member. */
    private final Map<String, Map<String, Integer>> counts = new ConcurrentHashMap<>();
    private volatile long membersLeft;

    /** @param kept true for a job whose tiles stay in the cluster when its render here stops (handed over) */
    TileFarm(ClusterData data, TileWorkers workers, Predicate<String> kept) {
        this.data = data;
        this.kept = kept;
        this.workers = workers;
        this.queue = data.queue();
    }

    /** A member left: every coordinator looks for its lost tiles now. */
    void memberLeft() {
        membersLeft++;
    }

    Map<String, Integer> workers(String jobId) {
        Map<String, Integer> count = counts.get(jobId);
        return count != null ? Map.copyOf(count) : Map.of();
    }

    /**
     * Renders the job's tiles on the cluster's members.
     *
     * @param resumed true for a job taken over: some of its tiles may be queued, claimed or done already
     * @param stop    turns true on cancel or at the job's deadline
     * @throws RenderCancelledException once {@code stop} is true
     * @throws JobFailedException       when a tile failed {@value #MAX_ATTEMPTS} times
     */
    RenderResult render(String jobId, CompiledScene scene, int tileSize, boolean resumed, RenderListener listener,
                        BooleanSupplier stop) {
        long start = System.nanoTime();
        int width = scene.settings().width(), height = scene.settings().height();
        List<TileRect> tiles = ClusterTiling.tiles(width, height, tileSize);
        SealedMap<Integer, TileResult> results = data.tiles(jobId);
        SealedMap<Integer, TileClaim> claims = data.claims(jobId);
        BlockingQueue<TileResult> arrived = new LinkedBlockingQueue<>();
        UUID registration = results.listen((index, result) -> arrived.add(result));
        workers.scenes().offer(jobId, scene);
        Map<String, Integer> count = counts.computeIfAbsent(jobId, id -> new ConcurrentHashMap<>());
        Job job = new Job(jobId, tiles, results, claims, new TileAssembly(tiles, new Film(width, height), listener, count));
        try {
            for (TileResult result : results.values()) {
                job.arrived(result); // a failed one: its coordinator died before it could retry it
            }
            Set<String> alive = alive();
            Map<Integer, TileClaim> claimed = resumed ? claims.entries() : Map.of();
            BitSet queued = resumed ? queued(jobId) : new BitSet();
            List<TileTask> todo = new ArrayList<>();
            for (int i = 0; i < tiles.size(); i++) {
                TileClaim claim = claimed.get(i);
                if (!job.assembly.done.get(i) && !queued.get(i) && (claim == null || !alive.contains(claim.member()))) {
                    todo.add(job.task(i, claim == null ? 0 : claim.attempt() + 1));
                }
            }
            queue.addAll(todo);
            long seenLeft = membersLeft;
            LostCheck lostCheck = new LostCheck(alive, System.nanoTime());
            long nextLostCheck = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(LOST_CHECK_MILLIS);
            long nextMissingCheck = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(MISSING_CHECK_MILLIS);
            while (job.assembly.doneCount < tiles.size()) {
                if (stop.getAsBoolean()) {
                    throw new RenderCancelledException();
                }
                TileResult result = arrived.poll(POLL_MILLIS, TimeUnit.MILLISECONDS);
                if (result != null) {
                    job.arrived(result);
                }
                long now = System.nanoTime();
                boolean left = seenLeft != membersLeft;
                if (left) {
                    seenLeft = membersLeft;
                    nextMissingCheck = Math.min(nextMissingCheck, now + TimeUnit.MILLISECONDS.toNanos(LOST_CHECK_MILLIS));
                }
                if (left || now - nextLostCheck > 0) {
                    nextLostCheck = now + TimeUnit.MILLISECONDS.toNanos(LOST_CHECK_MILLIS);
                    Set<String> members = alive();
                    if (lostCheck.due(now, left, members)) {
                        requeueLost(job, members);
                    }
                }
                if (now - nextMissingCheck > 0) {
                    boolean suspects = requeueMissing(job);
                    nextMissingCheck = System.nanoTime()
                            + TimeUnit.MILLISECONDS.toNanos(suspects ? LOST_CHECK_MILLIS : MISSING_CHECK_MILLIS);
                }
            }
            TileAssembly assembly = job.assembly;
            return new RenderResult(assembly.film, assembly.rays, assembly.nonFinite, System.nanoTime() - start,
                    assembly.samples);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new RenderCancelledException();
        } finally {
            results.removeListener(registration);
            workers.scenes().forget(jobId);
            // the tiles live on in the film, then in the image; cancelled or failed, they are of no use either;
            // handed over, they are the new owner's
            if (!kept.test(jobId)) {
                results.destroy();
                claims.destroy();
            }
        }
    }

    /** Forgets a job's worker counts (it was dropped). */
    void forget(String jobId) {
        counts.remove(jobId);
    }

    /** The job's tiles in the queue now. */
    private BitSet queued(String jobId) {
        BitSet queued = new BitSet();
        for (TileTask task : queue.snapshot()) {
            if (task.jobId().equals(jobId)) {
                queued.set(task.index());
            }
        }
        return queued;
    }

    private Set<String> alive() {
        Set<String> alive = new HashSet<>();
        for (Member each : data.member().getCluster().getMembers()) {
            alive.add(each.getUuid().toString());
        }
        return alive;
    }

    /**
     * Queues again the tiles claimed by members that have left, unless their result is in (a worker keeps
     * its claim once it has put its result, whose event may not have been heard yet).
     */
    private void requeueLost(Job job, Set<String> alive) {
        for (Map.Entry<Integer, TileClaim> entry : job.claims.entries().entrySet()) {
            int index = entry.getKey();
            TileClaim claim = entry.getValue();
            if (!job.assembly.done.get(index) && !alive.contains(claim.member()) && job.claims.remove(index, claim)) {
                TileResult result = job.results.get(index);
                if (result != null && result.attempt() == claim.attempt()) {
                    job.arrived(result);
                } else {
                    job.retry(index, claim.attempt(), "its member left the cluster");
                }
            }
        }
    }

    /**
     * Looks for the job's tiles in no state: not done here, not in the queue, not claimed. The queue is
     * read before the claims, so a tile taken meanwhile shows as claimed, unless its worker claims it
     * only after the claims were read: so a tile is taken for lost only when it was in no state at the
     * previous look too. The results of every tile neither done here nor queued are read first, claimed
     * or not (their events may have been lost, and a worker keeps its claim once its result is in).
     *
     * @return true if some tiles were in no state for the first time: the next look should come soon
     */
    private boolean requeueMissing(Job job) {
        BitSet missing = new BitSet();
        Collection<TileResult> unheard;
        try {
            BitSet queued = queued(job.id);
            Set<Integer> claimed = job.claims.keySet();
            BitSet done = job.assembly.done;
            Set<Integer> out = new HashSet<>();
            for (int i = done.nextClearBit(0); i < job.tiles.size(); i = done.nextClearBit(i + 1)) {
                if (!queued.get(i)) {
                    out.add(i);
                    if (!claimed.contains(i)) {
                        missing.set(i);
                    }
                }
            }
            unheard = out.isEmpty() ? List.of() : job.results.getAll(out).values();
        } catch (RuntimeException e) {
            log.warn("job {}: could not look for lost tiles ({}); looking again shortly", job.id, e.toString());
            return true;
        }
        for (TileResult result : unheard) {
            missing.clear(result.index());
            job.arrived(result);
        }
        BitSet lost = (BitSet) missing.clone();
        lost.and(job.suspects);
        missing.andNot(lost);
        job.suspects = missing;
        if (!lost.isEmpty()) {
            log.info("job {}: {} tiles were neither done, queued nor claimed, twice; queued again", job.id,
                    lost.cardinality());
            for (int i = lost.nextSetBit(0); i >= 0; i = lost.nextSetBit(i + 1)) {
                job.retry(i, job.attempts[i], "it was lost");
            }
        }
        return !missing.isEmpty();
    }

    /** A job's render on its coordinator: its tiles, where they are, and how often each was queued. */
    private final class Job {
        final String id;
        final List<TileRect> tiles;
        final SealedMap<Integer, TileResult> results;
        final SealedMap<Integer, TileClaim> claims;
        final TileAssembly assembly;
        /** The attempt each tile was last queued with by this coordinator. */
        final int[] attempts;
        /** The tiles in no state at the last look. */
        BitSet suspects = new BitSet();

        Job(String id, List<TileRect> tiles, SealedMap<Integer, TileResult> results, SealedMap<Integer, TileClaim> claims,
            TileAssembly assembly) {
            this.id = id;
            this.tiles = tiles;
            this.results = results;
            this.claims = claims;
            this.assembly = assembly;
            this.attempts = new int[tiles.size()];
        }

        TileTask task(int index, int attempt) {
            attempts[index] = Math.max(attempts[index], attempt);
            return new TileTask(id, index, attempt);
        }

        /** A tile's result: assembled, or if it failed, the tile is tried again; one that makes no sense is dropped. */
        void arrived(TileResult result) {
            String problem = assembly.problem(result);
            if (problem != null) {
                data.seal().reject(ClusterMaps.TILES_FAMILY, results.name(), problem);
                return;
            }
            assembly.accept(result);
            if (result.failed() && !assembly.done.get(result.index())) {
                retry(result.index(), result.attempt(), result.error());
            }
        }

        /** Queues the tile again as its next attempt, or fails the job if that would be one too many. */
        void retry(int index, int attempt, String why) {
            if (attempt + 1 >= MAX_ATTEMPTS) {
                TileRect tile = tiles.get(index);
                throw new JobFailedException("the tile at " + tile.x() + "," + tile.y() + " failed " + MAX_ATTEMPTS
                        + " times; the last time: " + why);
            }
            results.delete(index);
            queue.add(task(index, attempt + 1));
        }
    }
}

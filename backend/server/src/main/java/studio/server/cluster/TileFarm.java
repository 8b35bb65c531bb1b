package studio.server.cluster;

import java.util.ArrayList;
import java.util.BitSet;
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

import com.hazelcast.cluster.Member;
import com.hazelcast.collection.IQueue;
import com.hazelcast.core.EntryEvent;
import com.hazelcast.core.HazelcastInstance;
import com.hazelcast.map.IMap;
import com.hazelcast.map.listener.EntryAddedListener;
import com.hazelcast.map.listener.EntryUpdatedListener;

import studio.engine.render.Film;
import studio.engine.render.RenderCancelledException;
import studio.engine.render.RenderListener;
import studio.engine.render.RenderResult;
import studio.engine.render.Renderer;
import studio.engine.render.TileRect;
import studio.server.job.JobFailedException;
import studio.server.scene.compiling.CompiledScene;

/**
 * The coordinator of a job's render in the cluster, on the member that runs the job: queues the
 * job's tiles as tasks for every member's {@link TileWorkers}, assembles the results into the film
 * as they arrive (each tile once, reported to the job's listener), and queues again the tiles whose
 * worker died (their {@link TileClaim} names a member that left) or failed, at most
 * {@value #MAX_ATTEMPTS} times per tile; then the job fails, naming the tile. A member that takes
 * the job over runs the same loop: the tiles already in the job's tile map are assembled first,
 * and only the tiles neither done nor claimed by a live member are queued again.
 */
final class TileFarm {

    private static final org.slf4j.Logger log = org.slf4j.LoggerFactory.getLogger(TileFarm.class);

    /** A tile that failed or was lost with its member this often fails its job. */
    static final int MAX_ATTEMPTS = 3;
    /** The coordinator looks for results this often, and for the cancel and the deadline. */
    static final long POLL_MILLIS = 100;
    /** The coordinator looks for tiles lost with their members this often (and at once when one leaves). */
    static final long LOST_CHECK_MILLIS = 1_000;
    /**
     * When no tile has arrived for this long, the coordinator reads the tiles it has not heard of from
     * the job's tile map (map events are not delivered reliably while partitions move after a member
     * died) and queues again every tile that is neither done, nor claimed by a live member, nor in the
     * queue (a member killed in the middle of committing its take): such a tile costs at most this long.
     */
    static final long STALL_MILLIS = 5_000;

    private final HazelcastInstance member;
    private final TileWorkers workers;
    private final IQueue<TileTask> queue;
    /** The tiles each member rendered, per job of this member. */
    private final Map<String, Map<String, Integer>> counts = new ConcurrentHashMap<>();
    private volatile long membersLeft;

    TileFarm(HazelcastInstance member, TileWorkers workers) {
        this.member = member;
        this.workers = workers;
        this.queue = member.getQueue(ClusterMaps.TILE_QUEUE);
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
        List<TileRect> tiles = Renderer.tiles(width, height, tileSize);
        IMap<Integer, TileResult> results = member.getMap(ClusterMaps.tiles(jobId));
        IMap<Integer, TileClaim> claims = member.getMap(ClusterMaps.claims(jobId));
        BlockingQueue<TileResult> arrived = new LinkedBlockingQueue<>();
        UUID registration = results.addEntryListener(new Arrivals(arrived), true);
        workers.scenes().offer(jobId, scene);
        Map<String, Integer> count = counts.computeIfAbsent(jobId, id -> new ConcurrentHashMap<>());
        Assembly assembly = new Assembly(tiles, new Film(width, height), listener, count);
        try {
            List<TileResult> failed = new ArrayList<>();
            for (TileResult result : results.values()) {
                assembly.accept(result);
                if (result.failed()) {
                    failed.add(result); // its coordinator died before it could retry it
                }
            }
            for (TileResult result : failed) {
                if (!assembly.done.get(result.index())) {
                    retry(jobId, tiles, results, result.index(), result.attempt(), result.error());
                }
            }
            Set<String> alive = alive();
            List<TileTask> todo = new ArrayList<>();
            Map<Integer, TileClaim> claimed = resumed ? Map.copyOf(claims) : Map.of();
            BitSet queued = resumed ? queued(jobId) : new BitSet();
            for (int i = 0; i < tiles.size(); i++) {
                TileClaim claim = claimed.get(i);
                if (!assembly.done.get(i) && !queued.get(i) && (claim == null || !alive.contains(claim.member()))) {
                    todo.add(new TileTask(jobId, i, claim == null ? 0 : claim.attempt() + 1));
                }
            }
            queue.addAll(todo);
            long seenLeft = membersLeft;
            long nextCheck = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(LOST_CHECK_MILLIS);
            long lastArrival = System.nanoTime();
            while (assembly.doneCount < tiles.size()) {
                if (stop.getAsBoolean()) {
                    throw new RenderCancelledException();
                }
                TileResult result = arrived.poll(POLL_MILLIS, TimeUnit.MILLISECONDS);
                if (result == null && System.nanoTime() - lastArrival > TimeUnit.MILLISECONDS.toNanos(STALL_MILLIS)) {
                    lastArrival = System.nanoTime();
                    for (TileResult missed : unheard(results, tiles.size(), assembly.done)) {
                        assembly.accept(missed);
                        if (missed.failed() && !assembly.done.get(missed.index())) {
                            retry(jobId, tiles, results, missed.index(), missed.attempt(), missed.error());
                        }
                    }
                    requeueMissing(jobId, tiles.size(), claims, assembly.done);
                }
                if (result != null) {
                    lastArrival = System.nanoTime();
                    assembly.accept(result);
                    if (result.failed() && !assembly.done.get(result.index())) {
                        retry(jobId, tiles, results, result.index(), result.attempt(), result.error());
                    }
                }
                if (seenLeft != membersLeft || System.nanoTime() - nextCheck > 0) {
                    seenLeft = membersLeft;
                    nextCheck = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(LOST_CHECK_MILLIS);
                    requeueLost(jobId, tiles, claims, results, assembly.done);
                }
            }
            return new RenderResult(assembly.film, assembly.rays, assembly.nonFinite, System.nanoTime() - start,
                    assembly.samples);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new RenderCancelledException();
        } finally {
            results.removeEntryListener(registration);
            workers.scenes().forget(jobId);
            // the tiles live on in the film, then in the image; cancelled or failed, they are of no use either
            results.destroy();
            claims.destroy();
        }
    }

    /** Forgets a job's worker counts (it was dropped). */
    void forget(String jobId) {
        counts.remove(jobId);
    }

    /** The job's tiles in the queue now (a job taken over: its first member queued them). */
    private BitSet queued(String jobId) {
        BitSet queued = new BitSet();
        for (TileTask task : queue) {
            if (task.jobId().equals(jobId)) {
                queued.set(task.index());
            }
        }
        return queued;
    }

    private Set<String> alive() {
        Set<String> alive = new HashSet<>();
        for (Member each : member.getCluster().getMembers()) {
            alive.add(each.getUuid().toString());
        }
        return alive;
    }

    /** The results in the job's tile map of tiles not done here. */
    private static java.util.Collection<TileResult> unheard(IMap<Integer, TileResult> results, int count, BitSet done) {
        Set<Integer> open = new HashSet<>();
        for (int i = done.nextClearBit(0); i < count; i = done.nextClearBit(i + 1)) {
            open.add(i);
        }
        return results.getAll(open).values();
    }

    /** Queues the tiles that are neither done, nor claimed by a live member, nor queued. */
    private void requeueMissing(String jobId, int count, IMap<Integer, TileClaim> claims, BitSet done) {
        Set<String> alive = alive();
        Map<Integer, TileClaim> claimed = Map.copyOf(claims);
        BitSet queued = queued(jobId);
        List<TileTask> missing = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            TileClaim claim = claimed.get(i);
            if (!done.get(i) && !queued.get(i) && (claim == null || !alive.contains(claim.member()))) {
                missing.add(new TileTask(jobId, i, claim == null ? 0 : claim.attempt() + 1));
            }
        }
        if (!missing.isEmpty()) {
            log.info("job {}: {} tiles were neither done, claimed nor queued; queued again", jobId, missing.size());
            queue.addAll(missing);
        }
    }

    /** Queues again the tiles claimed by members that have left. */
    private void requeueLost(String jobId, List<TileRect> tiles, IMap<Integer, TileClaim> claims,
                             IMap<Integer, TileResult> results, BitSet done) {
        Set<String> alive = alive();
        for (Map.Entry<Integer, TileClaim> entry : claims.entrySet()) {
            int index = entry.getKey();
            TileClaim claim = entry.getValue();
            if (!done.get(index) && !alive.contains(claim.member()) && claims.remove(index, claim)) {
                retry(jobId, tiles, results, index, claim.attempt(), "its member left the cluster");
            }
        }
    }

    private void retry(String jobId, List<TileRect> tiles, IMap<Integer, TileResult> results, int index, int attempt,
                       String why) {
        if (attempt + 1 >= MAX_ATTEMPTS) {
            TileRect tile = tiles.get(index);
            throw new JobFailedException("the tile at " + tile.x() + "," + tile.y() + " failed " + MAX_ATTEMPTS
                    + " times; the last time: " + why);
        }
        results.delete(index);
        queue.add(new TileTask(jobId, index, attempt + 1));
    }

    /** The job's film as its tiles arrive: each tile once, reported in the order it arrived. */
    private static final class Assembly {
        final List<TileRect> tiles;
        final Film film;
        final RenderListener listener;
        final Map<String, Integer> count;
        final BitSet done = new BitSet();
        int doneCount;
        long rays, samples, nonFinite;

        Assembly(List<TileRect> tiles, Film film, RenderListener listener, Map<String, Integer> count) {
            this.tiles = tiles;
            this.film = film;
            this.listener = listener;
            this.count = count;
        }

        void accept(TileResult result) {
            if (result.failed() || done.get(result.index())) {
                return;
            }
            TileRect tile = tiles.get(result.index());
            double[] rgb = result.rgb();
            int i = 0;
            for (int y = tile.y(); y < tile.y() + tile.height(); y++) {
                for (int x = tile.x(); x < tile.x() + tile.width(); x++, i += 3) {
                    film.set(x, y, rgb[i], rgb[i + 1], rgb[i + 2]);
                }
            }
            done.set(result.index());
            doneCount++;
            rays += result.rays();
            samples += result.samples();
            nonFinite += result.nonFinite();
            count.merge(result.worker(), 1, Integer::sum);
            listener.tileFinished(film, tile, doneCount, tiles.size());
        }
    }

    /** Hands the job's tile map's new and replaced entries to the coordinator's thread. */
    private record Arrivals(BlockingQueue<TileResult> arrived)
            implements EntryAddedListener<Integer, TileResult>, EntryUpdatedListener<Integer, TileResult> {

        @Override
        public void entryAdded(EntryEvent<Integer, TileResult> event) {
            arrived.add(event.getValue());
        }

        @Override
        public void entryUpdated(EntryEvent<Integer, TileResult> event) {
            arrived.add(event.getValue());
        }
    }
}

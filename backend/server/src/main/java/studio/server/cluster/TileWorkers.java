package studio.server.cluster;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import com.hazelcast.collection.IQueue;
import com.hazelcast.core.HazelcastInstance;
import com.hazelcast.map.IMap;
import com.hazelcast.transaction.TransactionContext;
import com.hazelcast.transaction.TransactionOptions;

import studio.engine.render.Film;
import studio.engine.render.RenderCancelledException;
import studio.engine.render.Renderer;
import studio.engine.render.TileRect;
import studio.engine.render.TileRenderer;
import studio.server.scene.compiling.CompiledScene;
import studio.server.system.MemoryBusyException;

/**
 * This member's tile workers: threads that take tile tasks from the cluster's queue, every job's,
 * render them and put the results into the job's tile map, where the member that runs the job
 * assembles them. Taking a task and claiming it ({@link TileClaim}, naming this member) is one
 * transaction, so a tile is always queued, claimed or done: when a member dies, the tiles it had
 * claimed are queued again by their jobs' coordinators ({@link TileFarm}). On shutdown the workers
 * stop within a camera sample and hand their tiles back (queued again, claims dropped) before the
 * member leaves.
 */
final class TileWorkers implements AutoCloseable {

    private static final Logger log = LoggerFactory.getLogger(TileWorkers.class);
    /** A worker with nothing to do asks the queue again after this long: the bound of every wait. */
    static final long POLL_MILLIS = 500;
    /** A job's state is asked of the job table at most this often per member (not for every tile). */
    static final long JOB_CHECK_MILLIS = 1_000;
    /** Take and claim: one phase suffices, as a member lost mid-commit leaves its claims to be re-queued anyway. */
    private static final TransactionOptions TAKE = new TransactionOptions()
            .setTransactionType(TransactionOptions.TransactionType.ONE_PHASE);

    private record JobCheck(JobRecord job, long atNanos) {
    }

    private final HazelcastInstance member;
    private final String address;
    private final JobScenes scenes;
    private final IQueue<TileTask> queue;
    private final IMap<String, JobRecord> jobs;
    private final List<Worker> workers = new ArrayList<>();
    private final Map<String, JobCheck> checked = new ConcurrentHashMap<>();
    private volatile boolean running = true;

    TileWorkers(HazelcastInstance member, JobScenes scenes, int threads) {
        this.member = member;
        this.address = ClusterNames.address(member.getCluster().getLocalMember());
        this.scenes = scenes;
        this.queue = member.getQueue(ClusterMaps.TILE_QUEUE);
        this.jobs = member.getMap(ClusterMaps.JOBS);
        for (int i = 0; i < threads; i++) {
            Worker worker = new Worker();
            worker.thread = new Thread(worker, "tile-worker-" + (i + 1));
            worker.thread.setDaemon(true);
            workers.add(worker);
        }
    }

    void start() {
        workers.forEach(worker -> worker.thread.start());
    }

    JobScenes scenes() {
        return scenes;
    }

    String address() {
        return address;
    }

    /** Stops taking tiles, stops the ones being rendered and hands them back; waits for that, boundedly. */
    @Override
    public void close() {
        running = false;
        for (Worker worker : workers) {
            worker.stopTile();
        }
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        for (Worker worker : workers) {
            try {
                worker.thread.join(Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    private final class Worker implements Runnable {

        Thread thread;
        /** The job whose worker is cached, and the worker (one per thread, reused for its job's tiles). */
        private String jobId;
        private volatile TileRenderer renderer;

        @Override
        public void run() {
            while (running && member.getLifecycleService().isRunning()) {
                TileTask task;
                try {
                    task = take();
                } catch (RuntimeException e) {
                    if (running && member.getLifecycleService().isRunning()) {
                        log.warn("could not take a tile from the cluster's queue: {}", e.toString());
                    }
                    continue;
                }
                if (task != null) {
                    try {
                        render(task);
                    } catch (RuntimeException e) {
                        // the member is going (its claim, if any, is re-queued by the job's coordinator)
                        if (running && member.getLifecycleService().isRunning()) {
                            log.warn("could not report a tile to the cluster: {}", e.toString());
                        }
                    }
                }
            }
        }

        /** Takes a task and claims it in one transaction, waiting at most {@value #POLL_MILLIS} ms. */
        private TileTask take() {
            TransactionContext transaction = member.newTransactionContext(TAKE);
            transaction.beginTransaction();
            try {
                TileTask task = transaction.<TileTask>getQueue(ClusterMaps.TILE_QUEUE)
                        .poll(POLL_MILLIS, TimeUnit.MILLISECONDS);
                if (task != null) {
                    transaction.<Integer, TileClaim>getMap(ClusterMaps.claims(task.jobId()))
                            .set(task.index(), new TileClaim(member.getCluster().getLocalMember().getUuid().toString(),
                                    task.attempt()));
                }
                transaction.commitTransaction();
                return task;
            } catch (InterruptedException e) {
                transaction.rollbackTransaction();
                Thread.currentThread().interrupt();
                return null;
            } catch (RuntimeException e) {
                transaction.rollbackTransaction();
                throw e;
            }
        }

        private void render(TileTask task) {
            IMap<Integer, TileResult> results = member.getMap(ClusterMaps.tiles(task.jobId()));
            IMap<Integer, TileClaim> claims = member.getMap(ClusterMaps.claims(task.jobId()));
            JobRecord job = job(task.jobId());
            if (job == null || job.status().state().isFinal()) {
                // the job ended: its other tasks are dropped as they come
                claims.deleteAsync(task.index());
                scenes.forget(task.jobId());
                return;
            }
            try {
                CompiledScene scene = scenes.scene(task.jobId());
                if (scene == null) {
                    claims.delete(task.index());
                    return;
                }
                int width = scene.settings().width(), height = scene.settings().height();
                TileRect tile = Renderer.tiles(width, height, job.tileSize()).get(task.index());
                TileRenderer worker = worker(task.jobId(), scene);
                long rays = worker.rays(), samples = worker.samples();
                Film film = Film.ofTile(tile);
                long nonFinite = worker.render(film, tile);
                double[] rgb = new double[3 * tile.width() * tile.height()];
                int i = 0;
                for (int y = tile.y(); y < tile.y() + tile.height(); y++) {
                    for (int x = tile.x(); x < tile.x() + tile.width(); x++) {
                        for (int c = 0; c < 3; c++) {
                            rgb[i++] = film.get(x, y, c);
                        }
                    }
                }
                // not waited for: the next tile starts now; if this member dies first, its claim is still there.
                // The claim goes whether the put succeeded or not: a claim of a live member that outlives a lost
                // put would hide the tile from its coordinator for good (it re-queues only tiles neither done
                // nor claimed by a live member), while without it the tile is queued again within a stall's time.
                results.setAsync(task.index(), new TileResult(task.index(), task.attempt(), rgb, worker.rays() - rays,
                        worker.samples() - samples, nonFinite, address, null))
                        .whenComplete((ignored, failure) -> {
                            if (failure != null && running && member.getLifecycleService().isRunning()) {
                                log.warn("could not report tile {} of job {}: {}", task.index(), task.jobId(),
                                        failure.toString());
                            }
                            claims.deleteAsync(task.index());
                        });
            } catch (RenderCancelledException e) {
                handBack(task, claims); // shutting down: another member takes it
            } catch (MemoryBusyException e) {
                handBack(task, claims); // no memory for the scene now: another member, or this one later, takes it
                pause();
            } catch (RuntimeException | OutOfMemoryError e) {
                renderer = null;
                results.set(task.index(), TileResult.failed(task, address, e.getClass().getSimpleName()
                        + (e.getMessage() != null ? ": " + e.getMessage() : "")));
                claims.delete(task.index());
            }
        }

        /** Waits a poll's time before taking again, so that a tile this member cannot take now goes elsewhere. */
        private void pause() {
            try {
                Thread.sleep(POLL_MILLIS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }

        /** The job's record, asked of the job table at most every {@value #JOB_CHECK_MILLIS} ms. */
        private JobRecord job(String id) {
            long now = System.nanoTime();
            JobCheck check = checked.get(id);
            if (check == null || now - check.atNanos() > TimeUnit.MILLISECONDS.toNanos(JOB_CHECK_MILLIS)) {
                JobRecord job = jobs.get(id);
                if (job == null || job.status().state().isFinal()) {
                    checked.remove(id);
                    return job;
                }
                check = new JobCheck(job, now);
                checked.put(id, check);
            }
            return check.job();
        }

        private void handBack(TileTask task, IMap<Integer, TileClaim> claims) {
            renderer = null;
            jobId = null;
            queue.offer(task);
            claims.delete(task.index());
        }

        private TileRenderer worker(String id, CompiledScene scene) {
            TileRenderer current = renderer;
            if (current == null || !id.equals(jobId)) {
                current = new TileRenderer(scene.scene(), scene.settings());
                renderer = current;
                jobId = id;
            }
            if (!running) {
                current.stop();
            }
            return current;
        }

        void stopTile() {
            TileRenderer current = renderer;
            if (current != null) {
                current.stop();
            }
        }
    }
}

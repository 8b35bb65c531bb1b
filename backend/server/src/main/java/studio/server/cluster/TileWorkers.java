package studio.server.cluster;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import com.hazelcast.core.HazelcastInstance;

import studio.engine.render.Film;
import studio.engine.render.RenderCancelledException;
import studio.engine.render.TileRect;
import studio.engine.render.TileRenderer;
import studio.engine.render.TileRequest;
import studio.server.scene.compiling.CompiledScene;
import studio.server.system.MemoryBusyException;

/**
 * This member's tile workers: threads that take tile tasks from the cluster's queue, every job's,
 * render them and put the results into the job's tile map, where the member that runs the job
 * assembles them. A worker takes a task with a plain poll and then claims it ({@link TileClaim},
 * naming this member) in the job's claim map: no transaction, so nothing a dead member held can
 * hold up the others. (Taking and claiming in one transaction did: a member killed inside it kept
 * the claim's key locked for the transaction's timeout, two minutes, since Hazelcast releases a
 * departed member's locks but not its transactions' locks, which a one-phase transaction has no log
 * to roll back; every worker that took the tile again waited on that lock, the tile invisible in
 * its own transaction, until every worker of the cluster did.) For the moment between the poll and
 * the claim a tile is in no state, and a member that dies then loses it: the job's coordinator
 * ({@link TileFarm}) finds such tiles, as it finds the tiles claimed by members that left, and
 * queues them again. On shutdown the workers stop within a camera sample and hand their tiles back
 * (queued again, claims dropped) before the member leaves.
 *
 * <p>Taking and claiming are done ahead, by one fetcher thread a member, which keeps at most one
 * claimed task a worker {@linkplain #ready ready}: a worker that finishes a tile finds the next one
 * there instead of waiting for the two round trips to the members that own the queue and the claim.
 * Those members' cores are busy rendering, and each round trip waits for their network and
 * operation threads to be scheduled (milliseconds a task with two members pinned to one core each,
 * {@code scripts/cluster-scaling.sh}; taken ahead, a tenth of one). The price is at most one tile a worker holds beyond the one it
 * renders, which another member may wait for at the job's end.
 */
final class TileWorkers implements AutoCloseable {

    private static final Logger log = LoggerFactory.getLogger(TileWorkers.class);
    /** A worker with nothing to do asks the queue again after this long: the bound of every wait. */
    static final long POLL_MILLIS = 500;
    /** A job's state is asked of the job table at most this often per member (not for every tile). */
    static final long JOB_CHECK_MILLIS = 1_000;

    private record JobCheck(JobRecord job, long atNanos) {
    }

    private final ClusterData data;
    private final HazelcastInstance member;
    private final String memberId;
    private final String address;
    private final JobScenes scenes;
    private final SealedQueue<TileTask> queue;
    private final SealedMap<String, JobRecord> jobs;
    private final List<Worker> workers = new ArrayList<>();
    private final Thread fetcher;
    /** Claimed tasks taken ahead, at most one a worker ({@link #room} counts the places left). */
    private final BlockingQueue<TileTask> ready;
    private final Semaphore room;
    private final Map<String, JobCheck> checked = new ConcurrentHashMap<>();
    private final Steps steps;
    private volatile boolean running = true;

    /** The steps of a take, where a test kills a member with a take half done; nothing in the application. */
    interface Steps {
        Steps NONE = new Steps() {
        };

        /** The task is out of the queue and not claimed yet. */
        default void taken(TileTask task) {
        }

        /** The task is claimed and not rendered yet. */
        default void claimed(TileTask task) {
        }
    }

    TileWorkers(ClusterData data, JobScenes scenes, int threads) {
        this(data, scenes, threads, Steps.NONE);
    }

    TileWorkers(ClusterData data, JobScenes scenes, int threads, Steps steps) {
        this.data = data;
        this.member = data.member();
        this.memberId = member.getCluster().getLocalMember().getUuid().toString();
        this.address = ClusterNames.address(member.getCluster().getLocalMember());
        this.scenes = scenes;
        this.queue = data.queue();
        this.jobs = data.jobs();
        this.steps = steps;
        for (int i = 0; i < threads; i++) {
            Worker worker = new Worker();
            worker.thread = new Thread(worker, "tile-worker-" + (i + 1));
            worker.thread.setDaemon(true);
            workers.add(worker);
        }
        this.ready = new ArrayBlockingQueue<>(threads);
        this.room = new Semaphore(threads);
        this.fetcher = new Thread(this::fetch, "tile-fetcher");
        fetcher.setDaemon(true);
    }

    void start() {
        fetcher.start();
        workers.forEach(worker -> worker.thread.start());
    }

    JobScenes scenes() {
        return scenes;
    }

    ClusterData data() {
        return data;
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
        List<Thread> threads = new ArrayList<>();
        threads.add(fetcher);
        workers.forEach(worker -> threads.add(worker.thread));
        for (Thread thread : threads) {
            try {
                thread.join(Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
        // the tasks taken ahead go back, too, while the member can still say so; if it cannot (it was
        // terminated), their claims name a member that left, and their jobs' coordinators queue them again
        for (TileTask task; (task = ready.poll()) != null; ) {
            try {
                if (member.getLifecycleService().isRunning()) {
                    handBack(task);
                }
            } catch (RuntimeException e) {
                log.debug("could not hand tile {} of job {} back: {}", task.index(), task.jobId(), e.toString());
            }
        }
    }

    /** The fetcher: takes and claims a task whenever a place is free, so that each worker finds its next one ready. */
    private void fetch() {
        while (running && member.getLifecycleService().isRunning()) {
            try {
                if (!room.tryAcquire(POLL_MILLIS, TimeUnit.MILLISECONDS)) {
                    continue;
                }
            } catch (InterruptedException e) {
                return;
            }
            TileTask task = null;
            try {
                task = take();
            } catch (RuntimeException e) {
                if (running && member.getLifecycleService().isRunning()) {
                    log.warn("could not take a tile from the cluster's queue: {}", e.toString());
                }
            }
            if (task != null) {
                ready.add(task); // there is a place: the permit
            } else {
                room.release();
            }
        }
    }

    /** Takes a task and claims it, waiting at most {@value #POLL_MILLIS} ms for one. */
    private TileTask take() {
        TileTask task;
        try {
            task = queue.poll(POLL_MILLIS, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return null;
        }
        if (task != null) {
            steps.taken(task);
            data.claims(task.jobId()).set(task.index(), new TileClaim(memberId, task.attempt()));
            steps.claimed(task);
        }
        return task;
    }

    /** Gives a task back to the queue for another member (or this one, later) and drops this member's claim. */
    private void handBack(TileTask task) {
        queue.offer(task);
        data.claims(task.jobId()).delete(task.index());
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
                    task = ready.poll(POLL_MILLIS, TimeUnit.MILLISECONDS);
                } catch (InterruptedException e) {
                    return;
                }
                if (task != null) {
                    room.release();
                    if (!running) {
                        handBack(task); // shutting down: another member takes it
                        continue;
                    }
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

        private void render(TileTask task) {
            SealedMap<Integer, TileResult> results = data.tiles(task.jobId());
            SealedMap<Integer, TileClaim> claims = data.claims(task.jobId());
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
                TileRect tile = ClusterTiling.tiles(width, height, job.tileSize()).get(task.index());
                TileRenderer worker = worker(task.jobId(), scene);
                long rays = worker.rays(), samples = worker.samples();
                Film film = Film.ofTile(tile);
                long nonFinite = worker.render(TileRequest.whole(film, tile));
                double[] rgb = film.pixels(tile);
                // not waited for: the next tile starts now; if this member dies first, its claim is still there.
                // A claim stays once its result is in: the coordinator reads results before claims, and a claim of a
                // tile with a result costs nothing, while deleting it was two of a tile's round trips (its backup).
                // A lost put's claim goes: a claim of a live member would otherwise hide the tile from its coordinator
                // until its next look at the results (TileFarm#requeueMissing).
                results.setAsync(task.index(), new TileResult(task.index(), task.attempt(), rgb, worker.rays() - rays,
                        worker.samples() - samples, nonFinite, address, null))
                        .whenComplete((ignored, failure) -> {
                            if (failure != null) {
                                if (running && member.getLifecycleService().isRunning()) {
                                    log.warn("could not report tile {} of job {}: {}", task.index(), task.jobId(),
                                            failure.toString());
                                }
                                claims.deleteAsync(task.index());
                            }
                        });
            } catch (RenderCancelledException e) {
                giveBack(task); // shutting down: another member takes it
            } catch (MemoryBusyException e) {
                giveBack(task); // no memory for the scene now: another member, or this one later, takes it
                pause();
            } catch (RuntimeException | OutOfMemoryError e) {
                renderer = null;
                log.warn("tile {} of job {} failed here", task.index(), task.jobId(), e);
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

        /** Hands the task back and forgets the job's renderer. */
        private void giveBack(TileTask task) {
            renderer = null;
            jobId = null;
            handBack(task);
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

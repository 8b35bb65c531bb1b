package studio.server.cluster;

import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import com.hazelcast.cluster.Member;
import com.hazelcast.cluster.MembershipEvent;
import com.hazelcast.cluster.MembershipListener;
import com.hazelcast.core.HazelcastInstance;

import studio.engine.render.RenderListener;
import studio.engine.render.RenderResult;
import studio.engine.render.Renderer;
import studio.server.job.JobCluster;
import studio.server.job.JobListener;
import studio.server.job.JobState;
import studio.server.job.JobStatus;
import studio.server.render.RenderBudget;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;

/**
 * Jobs in a cluster of several members (see {@link JobCluster}): the job table, scenes, images and
 * event logs live in the cluster's maps and ring buffers, each with a backup; a job's tiles are
 * rendered by every member ({@link TileFarm}, {@link TileWorkers}); any member serves any job's
 * status, events, image and cancel; and when a member leaves, the others take over its unfinished
 * jobs: of those that try, the one whose {@link TakeOver} succeeds runs the job from the tiles done.
 */
public final class ClusterJobs implements JobCluster, AutoCloseable {

    private static final Logger log = LoggerFactory.getLogger(ClusterJobs.class);
    /** Besides on every member's departure, orphaned jobs are looked for this often. */
    static final long ORPHAN_CHECK_SECONDS = 5;
    /** Streams of other members' jobs hear a heartbeat this often, as the job service's own streams do. */
    static final long REMOTE_HEARTBEAT_SECONDS = 5;
    /** A job's end is written to the cluster's maps within this long before the job reports it, or after. */
    static final long END_WRITE_SECONDS = 10;
    /**
     * The cluster's tiles are this large when the image has at least {@value #MIN_LARGE_TILES} of
     * them: each tile costs a few round trips between members (take and claim it, put its result,
     * log its event), a few milliseconds each on a busy machine (docs/cluster.md, scaling).
     */
    static final int LARGE_TILE = 64;
    static final int MIN_LARGE_TILES = 64;

    private final HazelcastInstance member;
    private final ClusterData data;
    private final String memberId;
    private final SceneCompiler compiler;
    private final TileWorkers workers;
    private final TileFarm farm;
    private final int renderThreads;
    private final SealedMap<String, JobRecord> jobs;
    private final SealedMap<String, byte[]> scenes;
    private final SealedMap<String, byte[]> images;
    private final SealedMap<String, String> cancels;
    private final SealedMap<String, Long> seen;
    /** Jobs whose cancel was asked for through another member. */
    private final Set<String> cancelRequested = ConcurrentHashMap.newKeySet();
    /** Jobs this member took over and has not rendered yet: their tiles may be queued already. */
    private final Set<String> adopted = ConcurrentHashMap.newKeySet();
    private final ScheduledExecutorService background;
    /** Writes a job's end to the job table (a compare-and-set, which has no asynchronous form), waited for in bounds. */
    private final ExecutorService endWrites = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "cluster-end-writes");
        t.setDaemon(true);
        return t;
    });
    /** The event streams this member serves of other members' jobs, by listener. */
    private final Map<JobListener, RemoteJobStream> remoteStreams = new ConcurrentHashMap<>();
    private final long remoteHeartbeatMillis;
    private final HandOver handOver;
    private volatile Takeover takeover;
    private UUID membershipRegistration, cancelRegistration, releaseRegistration;

    /** @param renderThreads threads per render, 0 for all cores: fixes a job's tiling, as on one member */
    ClusterJobs(SceneCompiler compiler, TileWorkers workers, int renderThreads) {
        this(compiler, workers, renderThreads, TimeUnit.SECONDS.toMillis(REMOTE_HEARTBEAT_SECONDS));
    }

    /** As above, with the streams of other members' jobs hearing a heartbeat every {@code remoteHeartbeatMillis} (tests). */
    ClusterJobs(SceneCompiler compiler, TileWorkers workers, int renderThreads, long remoteHeartbeatMillis) {
        this.remoteHeartbeatMillis = remoteHeartbeatMillis;
        this.data = workers.data();
        this.member = data.member();
        this.memberId = member.getCluster().getLocalMember().getUuid().toString();
        this.compiler = compiler;
        this.workers = workers;
        this.handOver = new HandOver(data.jobs(), memberId);
        this.farm = new TileFarm(data, workers, handOver::handedOver);
        this.renderThreads = renderThreads;
        this.jobs = data.jobs();
        this.scenes = data.scenes();
        this.images = data.images();
        this.cancels = data.cancels();
        this.seen = data.seen();
        this.background = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "cluster-jobs");
            t.setDaemon(true);
            return t;
        });
    }

    @Override
    public void start(Takeover takeover) {
        this.takeover = takeover;
        // only a cancel sealed by a member counts: one that does not open is dropped (and counted)
        cancelRegistration = cancels.listen((id, reason) -> cancelRequested.add(id));
        membershipRegistration = member.getCluster().addMembershipListener(new MembershipListener() {
            @Override
            public void memberAdded(MembershipEvent event) {
            }

            @Override
            public void memberRemoved(MembershipEvent event) {
                farm.memberLeft();
                background.execute(ClusterJobs.this::adoptOrphans);
            }
        });
        // a job released by a stopping member is taken over at once
        releaseRegistration = jobs.listen((id, job) -> {
            if (HandOver.RELEASED.equals(job.owner()) && !job.status().state().isFinal() && !handOver.leaving()) {
                background.execute(this::adoptOrphans);
            }
        });
        background.scheduleWithFixedDelay(this::adoptOrphans, ORPHAN_CHECK_SECONDS, ORPHAN_CHECK_SECONDS,
                TimeUnit.SECONDS);
        background.scheduleWithFixedDelay(this::heartbeatRemoteStreams, remoteHeartbeatMillis, remoteHeartbeatMillis,
                TimeUnit.MILLISECONDS);
        workers.start();
    }

    @Override
    public RenderResult render(String id, CompiledScene scene, RenderBudget budget, RenderListener listener,
                               BooleanSupplier cancelled) {
        JobRecord job = jobs.get(id);
        int tileSize = job != null ? job.tileSize() : tileSize(scene.settings().width(), scene.settings().height());
        boolean resumed = adopted.remove(id);
        return budget.withinTime(() -> cancelled.getAsBoolean() || cancelRequested.contains(id)
                        || handOver.handedOver(id),
                stop -> farm.render(id, scene, tileSize, resumed, listener, stop));
    }

    /**
     * The cluster's tile size: {@value #LARGE_TILE}-pixel tiles when there are enough of them, else this
     * member's own (see {@link Renderer#tileSize}); {@link ClusterTiling} cuts the image's top rows
     * into tiles twice as large. The image is the same whatever the tiling: each pixel is seeded from
     * itself.
     */
    private int tileSize(int width, int height) {
        long large = (long) ((width + LARGE_TILE - 1) / LARGE_TILE) * ((height + LARGE_TILE - 1) / LARGE_TILE);
        return large >= MIN_LARGE_TILES ? LARGE_TILE : Renderer.tileSize(width, height,
                renderThreads > 0 ? renderThreads : Runtime.getRuntime().availableProcessors());
    }

    @Override
    public Map<String, Integer> workers(String id) {
        return farm.workers(id);
    }

    @Override
    public JobListener accepted(String id, String principal, byte[] sceneJson, Supplier<JobStatus> status, Supplier<byte[]> image,
                                boolean resumed) {
        EventLog events = data.events(id);
        JobStatus now = status.get();
        int tileSize;
        Set<String> published = ConcurrentHashMap.newKeySet();
        if (resumed) {
            JobRecord job = jobs.get(id);
            tileSize = job != null ? job.tileSize() : tileSize(now.width(), now.height());
            published.addAll(events.publishedTiles(END_WRITE_SECONDS));
        } else {
            tileSize = tileSize(now.width(), now.height());
            scenes.set(id, sceneJson);
            jobs.set(id, new JobRecord(now, memberId, tileSize, principal));
        }
        return new JobPublisher(id, memberId, jobs, images, events, status, image, published,
                () -> handOver.handedOver(id));
    }

    /**
     * Writes the end of a job of this member that ran (a done job's image first, then the job table), so
     * that the job reports its end only once every member serves it, image and all. A write that
     * fails or takes more than {@value #END_WRITE_SECONDS} s is left to the job's {@link JobPublisher},
     * which writes the end again when the job reports it; a done end is never written without its image.
     */
    @Override
    public void ending(String id, JobStatus end, byte[] image) {
        if (handOver.handedOver(id)) {
            return; // it ends on another member
        }
        try {
            if (end.state() == JobState.DONE) {
                images.setAsync(id, image).toCompletableFuture().get(END_WRITE_SECONDS, TimeUnit.SECONDS);
            }
            CompletableFuture.runAsync(() -> jobs.update(id, new StatusUpdate(memberId, end)), endWrites)
                    .get(END_WRITE_SECONDS, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (ExecutionException | TimeoutException | RuntimeException e) {
            if (member.getLifecycleService().isRunning()) {
                log.warn("could not write the end of job {} to the cluster's maps: {}", id, e.toString());
            }
        }
    }

    @Override
    public JobStatus status(String id, String principal) {
        JobRecord job = jobs.get(id);
        if (job == null || !job.belongsTo(principal)) {
            return null;
        }
        seen.setAsync(id, System.currentTimeMillis());
        return job.status();
    }

    @Override
    public byte[] image(String id, String principal) {
        JobRecord job = jobs.get(id);
        if (job == null || !job.belongsTo(principal)) {
            return null;
        }
        seen.setAsync(id, System.currentTimeMillis());
        return images.get(id);
    }

    @Override
    public JobStatus cancel(String id, String principal) {
        JobRecord job = jobs.get(id);
        if (job == null || !job.belongsTo(principal)) {
            return null;
        }
        if (!job.status().state().isFinal()) {
            cancels.set(id, "cancelled", 1, TimeUnit.HOURS);
        }
        return job.status();
    }

    @Override
    public boolean subscribe(String id, String principal, JobListener listener, Executor sender) {
        JobRecord job = jobs.get(id);
        if (job == null || !job.belongsTo(principal)) {
            return false;
        }
        seen.setAsync(id, System.currentTimeMillis());
        RemoteJobStream stream = new RemoteJobStream(id, jobs, data.events(id), listener,
                sender, () -> remoteStreams.remove(listener));
        remoteStreams.put(listener, stream);
        stream.start(job);
        return true;
    }

    @Override
    public void unsubscribe(String id, JobListener listener) {
        RemoteJobStream stream = remoteStreams.get(listener);
        if (stream != null) {
            stream.close();
        }
    }

    /**
     * Every {@value #REMOTE_HEARTBEAT_SECONDS} s, as this member's own jobs do for their streams: each
     * event stream of another member's job checks its connection (a keep-alive), and the job is marked
     * seen, so that its owner does not cancel it as abandoned while a client watches it through here.
     */
    private void heartbeatRemoteStreams() {
        Set<String> watched = new HashSet<>();
        for (RemoteJobStream stream : remoteStreams.values()) {
            stream.heartbeat();
            watched.add(stream.jobId());
        }
        long now = System.currentTimeMillis();
        for (String id : watched) {
            seen.setAsync(id, now);
        }
    }

    @Override
    public long lastSeenMillis(String id) {
        Long millis = seen.get(id);
        return millis != null ? millis : 0;
    }

    @Override
    public void dropped(String id) {
        jobs.delete(id);
        scenes.delete(id);
        images.delete(id);
        cancels.delete(id);
        seen.delete(id);
        data.events(id).destroy();
        cancelRequested.remove(id);
        farm.forget(id);
    }

    /** Takes over the unfinished jobs whose member has left, those this member wins. */
    void adoptOrphans() {
        Takeover resume = takeover;
        if (resume == null || handOver.leaving() || !member.getLifecycleService().isRunning()) {
            return;
        }
        try {
            Set<String> alive = new HashSet<>();
            for (Member each : member.getCluster().getMembers()) {
                alive.add(each.getUuid().toString());
            }
            for (Map.Entry<String, JobRecord> entry : jobs.entries().entrySet()) {
                JobRecord job = entry.getValue();
                if (job.status().state().isFinal() || alive.contains(job.owner())) {
                    continue;
                }
                String id = entry.getKey();
                if (jobs.update(id, new TakeOver(job.owner(), memberId))) {
                    adopt(id, job, resume);
                }
            }
        } catch (RuntimeException e) {
            log.warn("could not look for jobs of members that left: {}", e.toString());
        }
    }

    private void adopt(String id, JobRecord job, Takeover resume) {
        try {
            byte[] json = scenes.get(id);
            if (json == null) {
                throw new IllegalStateException("its scene is gone");
            }
            CompiledScene scene = compiler.compile(CompileRequest.of(json));
            adopted.add(id);
            resume.resume(id, job.principal(), scene, json);
            log.info("took over job {} from a member that left", id);
        } catch (RuntimeException e) {
            adopted.remove(id);
            log.warn("could not take over job {}: {}", id, e.toString());
            JobStatus was = job.status();
            JobStatus failed = new JobStatus(id, JobState.FAILED, was.progress(), was.elapsedMillis(), null, was.width(),
                    was.height(), was.fileName(), was.mediaType(), "the member running the job left the cluster, and "
                    + "no other could take it over", was.workers());
            jobs.set(id, job.withOwner(memberId).withStatus(failed));
            data.events(id).add(failed);
        }
    }

    /**
     * Hands this member's unfinished jobs to the others (see {@link HandOver}): its workers stop and
     * hand back their tiles first; its event streams of other members' jobs are dropped.
     */
    @Override
    public boolean canHandOver() {
        return !handOver.leaving() && member.getLifecycleService().isRunning()
                && member.getCluster().getMembers().size() > 1;
    }

    @Override
    public void handOver(Set<String> ids) {
        log.info("handing {} jobs to the other members", ids.size());
        workers.close();
        handOver.release(ids);
        // this member's streams of other members' jobs end too: their clients reconnect through another member
        remoteStreams.values().forEach(RemoteJobStream::drop);
    }

    @Override
    public boolean awaitHandedOver(long deadlineNanos) throws InterruptedException {
        return handOver.await(deadlineNanos);
    }

    @Override
    public void close() {
        background.shutdownNow();
        endWrites.shutdownNow();
        workers.close();
        if (member.getLifecycleService().isRunning()) {
            try {
                member.getCluster().removeMembershipListener(membershipRegistration);
                cancels.removeListener(cancelRegistration);
                jobs.removeListener(releaseRegistration);
            } catch (RuntimeException e) {
                // the member is going anyway
            }
        }
    }
}

package studio.server.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import com.hazelcast.map.MapInterceptor;

import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.server.Await;
import studio.server.job.JobRequests;
import studio.server.job.JobListener;
import studio.server.job.JobState;
import studio.server.job.JobStatus;
import studio.server.job.TileEvent;
import studio.server.render.ImageFiles;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;

/**
 * Several members in one JVM, on loopback: a job accepted by one member is served by every member
 * (status, events, image, cancel), its tiles are rendered by all of them, its image is the bytes
 * one machine's render gives, and it ends done with those bytes when a worker, or the member that
 * accepted it, dies mid-render, or a worker leaves gracefully.
 */
class ClusterJobsTest {

    /** A glass scene of 20 tiles (32x32 at one thread per member), about two seconds of work on one core. */
    static final String SCENE = """
            {"name": "cluster-test", "image": {"width": 160, "height": 120, "format": "png"},
             "camera": {"position": [0, 1.2, 5], "lookAt": [0, 0.5, 0]},
             "render": {"sampler": "jittered", "samples": 24, "maxDepth": 8, "seed": 7},
             "objects": [{"type": "sphere", "center": [-0.6, 0.5, 0], "radius": 0.5, "material": {"type": "glass"}},
                         {"type": "sphere", "center": [0.6, 0.5, 0], "radius": 0.5, "material": {"type": "mirror"}},
                         {"type": "plane"}]}
            """;
    static final long WAIT_MILLIS = 60_000;
    static final int TILES = ClusterTiling.tiles(160, 120, Renderer.tileSize(160, 120, 1)).size();

    private static byte[] oneMachine;

    private final List<TestMember> members = new ArrayList<>();
    private final String name = "test-" + UUID.randomUUID();

    @BeforeAll
    static void renderOnOneMachine() {
        CompiledScene scene = SceneCompiler.standalone(TestMember.VALIDATION::getValidator)
                .compile(CompileRequest.of(SCENE.getBytes(StandardCharsets.UTF_8)));
        oneMachine = ImageFiles.encode(Renderer.render(RenderRequest.of(scene.scene(), scene.settings())).film(), scene.format(),
                scene.quality());
    }

    @AfterEach
    void stopMembers() {
        for (TestMember member : members) {
            member.kill();
        }
    }

    private void start(int count) throws Exception {
        int[] ports = new int[count];
        for (int i = 0; i < count; i++) {
            ports[i] = TestMember.BASE_PORT + i;
        }
        for (int port : ports) {
            members.add(new TestMember(name, port, ports));
        }
        for (TestMember member : members) {
            assertThat(member.hazelcast.getCluster().getMembers()).hasSize(count);
        }
        // every partition's backup in place: a member killed before then may take data with it
        Await.until("the cluster to be safe", WAIT_MILLIS,
                () -> members.stream().allMatch(member -> member.hazelcast.getPartitionService().isClusterSafe()));
    }

    private String submit(TestMember member) {
        byte[] json = SCENE.getBytes(StandardCharsets.UTF_8);
        CompiledScene scene = SceneCompiler.standalone(TestMember.VALIDATION::getValidator).compile(CompileRequest.of(json));
        return member.jobs.submit(JobRequests.of(scene, json)).id();
    }

    private static JobStatus awaitFinal(TestMember member, String id) throws Exception {
        Await.until("job " + id + " to end, seen through " + member.address, WAIT_MILLIS,
                () -> member.jobs.status(id).state().isFinal());
        return member.jobs.status(id);
    }

    private static int tilesOf(JobStatus status, TestMember member) {
        return status.workers() == null ? 0 : status.workers().getOrDefault(member.address, 0);
    }

    @Test
    void anyMemberServesAJobThatEveryMemberRendersToOneMachinesBytes() throws Exception {
        start(3);
        TestMember accepting = members.get(0), other = members.get(1);
        String id = submit(accepting);

        List<Object> events = new CopyOnWriteArrayList<>();
        assertThat(other.cluster.subscribe(id, "", recorder(events), Executors.newSingleThreadExecutor())).isTrue();
        JobStatus done = awaitFinal(members.get(2), id);

        assertThat(done.state()).isEqualTo(JobState.DONE);
        assertThat(awaitFinal(other, id).state()).isEqualTo(JobState.DONE);
        assertThat(other.jobs.image(id).bytes()).isEqualTo(oneMachine);
        assertThat(members.get(2).jobs.image(id).bytes()).isEqualTo(oneMachine);
        assertThat(done.workers().values().stream().mapToInt(Integer::intValue).sum()).isEqualTo(TILES);
        assertThat(done.workers()).containsOnlyKeys(members.stream().map(member -> member.address).toList());
        Await.until("the event stream through another member to end", WAIT_MILLIS,
                () -> !events.isEmpty() && events.get(events.size() - 1) instanceof String);
        assertThat(events.stream().filter(TileEvent.class::isInstance)).hasSize(TILES);
        assertThat(events.get(events.size() - 1)).isEqualTo("end done");
    }

    @Test
    void aCancelThroughAnotherMemberStopsTheJob() throws Exception {
        start(2);
        String id = submit(members.get(0));
        Await.until("the job to run", WAIT_MILLIS, () -> members.get(1).jobs.status(id).state() == JobState.RUNNING);

        members.get(1).jobs.cancel(id);

        assertThat(awaitFinal(members.get(1), id).state()).isEqualTo(JobState.CANCELLED);
    }

    @Test
    void aWorkerKilledMidRenderLosesNoTile() throws Exception {
        start(3);
        TestMember accepting = members.get(0), worker = members.get(2);
        String id = submit(accepting);
        Await.until("the worker to render a tile", WAIT_MILLIS, () -> tilesOf(accepting.jobs.status(id), worker) > 0);
        assertThat(accepting.jobs.status(id).state()).isEqualTo(JobState.RUNNING);

        worker.kill();

        assertThat(awaitFinal(members.get(1), id).state()).isEqualTo(JobState.DONE);
        assertThat(members.get(1).jobs.image(id).bytes()).isEqualTo(oneMachine);
    }

    @Test
    void anotherMemberTakesOverTheJobOfTheAcceptingMemberKilledMidRender() throws Exception {
        start(3);
        TestMember accepting = members.get(0), reader = members.get(1);
        String id = submit(accepting);
        Await.until("a few tiles", WAIT_MILLIS, () -> accepting.jobs.status(id).progress() > 0.05);

        accepting.kill();

        JobStatus end = awaitFinal(reader, id);
        assertThat(end.state()).as(end.error() == null ? "" : end.error()).isEqualTo(JobState.DONE);
        assertThat(reader.jobs.image(id).bytes()).isEqualTo(oneMachine);
        assertThat(members.get(2).jobs.image(id).bytes()).isEqualTo(oneMachine);
    }

    /**
     * A worker that dies between taking a tile from the queue and claiming it leaves the tile in no
     * state at all (neither queued, claimed nor done): its job's owner finds it missing and queues it again.
     */
    @Test
    void aWorkerKilledBetweenTakingATileAndClaimingItLosesNoTile() throws Exception {
        start(3);
        TestMember worker = members.get(2);
        List<TileTask> taken = new CopyOnWriteArrayList<>();
        worker.onTaken = task -> {
            taken.add(task);
            worker.die();
        };
        String id = submit(members.get(0));

        assertThat(awaitFinal(members.get(1), id).state()).isEqualTo(JobState.DONE);
        assertThat(taken).hasSize(1);
        assertThat(members.get(1).jobs.image(id).bytes()).isEqualTo(oneMachine);
    }

    /**
     * A worker that dies right after claiming a tile: the claim names a member that left, so the tile is
     * queued again, and the next worker to take it is not held up by anything the dead one left behind.
     * (Taking and claiming in one transaction, a worker killed there left the claim's key locked for the
     * transaction's timeout, two minutes, when the key lived on another member: the other workers hold
     * their first tiles until the worker died, so that it claims tiles until one of those.)
     */
    @Test
    void aWorkerKilledRightAfterClaimingATileLosesNoTile() throws Exception {
        start(3);
        TestMember worker = members.get(2);
        CountDownLatch died = new CountDownLatch(1);
        for (TestMember other : members.subList(0, 2)) {
            other.onTaken = task -> awaitQuietly(died);
        }
        List<TileTask> claimed = new CopyOnWriteArrayList<>();
        worker.onClaimed = task -> {
            if (!worker.hazelcast.getPartitionService().getPartition(task.index()).getOwner().localMember()) {
                claimed.add(task);
                worker.die();
                died.countDown();
            }
        };
        String id = submit(members.get(0));

        assertThat(awaitFinal(members.get(1), id).state()).isEqualTo(JobState.DONE);
        assertThat(claimed).hasSize(1);
        assertThat(members.get(1).jobs.image(id).bytes()).isEqualTo(oneMachine);
    }

    /**
     * A stream of another member's job hears heartbeats while the job is quiet, as a stream of this
     * member's own job does (an event stream sends a keep-alive and so finds out that its client left),
     * and keeps the job marked seen, so that its owner does not cancel it as abandoned while someone
     * watches it through another member; once its listener is unsubscribed it hears nothing more.
     */
    @Test
    void aStreamThroughAnotherMemberHearsHeartbeatsAndNothingOnceItsListenerLeft() throws Exception {
        start(2);
        CountDownLatch go = new CountDownLatch(1);
        for (TestMember member : members) {
            member.onTaken = task -> awaitQuietly(go); // no tile finishes: a quiet job
        }
        String id = submit(members.get(0));
        TestMember other = members.get(1);
        List<Object> events = new CopyOnWriteArrayList<>();
        AtomicInteger heartbeats = new AtomicInteger();
        JobListener listener = recorder(events, heartbeats);
        assertThat(other.cluster.subscribe(id, "", listener, Executors.newCachedThreadPool())).isTrue();
        long seenAtSubscribe = other.cluster.lastSeenMillis(id);
        Await.until("heartbeats of a quiet job through another member", WAIT_MILLIS, () -> heartbeats.get() >= 3);
        Await.until("the job marked seen by the heartbeats", WAIT_MILLIS,
                () -> other.cluster.lastSeenMillis(id) > seenAtSubscribe);
        assertThat(events).noneMatch(TileEvent.class::isInstance);

        other.cluster.unsubscribe(id, listener);
        int heartbeatsThen = heartbeats.get();
        go.countDown();
        assertThat(awaitFinal(other, id).state()).isEqualTo(JobState.DONE);
        pause(3 * TestMember.REMOTE_HEARTBEAT_MILLIS);
        assertThat(events).as("no tile and no end once the listener left").noneMatch(
                event -> event instanceof TileEvent || event instanceof String);
        assertThat(heartbeats.get()).as("a heartbeat under way when it left, at most").isLessThanOrEqualTo(heartbeatsThen + 1);
    }

    private static void awaitQuietly(CountDownLatch latch) {
        try {
            latch.await(WAIT_MILLIS, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * A job taken over is done with its image through every member at once: no member answers done
     * while another cannot serve the image yet. The image's write takes a second here, so that a new
     * owner that answered done before the cluster's maps had the job's end would show it. (That the
     * owner serves the image while the maps already have the end is JobServiceTest's.)
     */
    @Test
    void aTakenOverJobIsDoneWithItsImageThroughEveryMemberAtOnce() throws Exception {
        start(3);
        TestMember accepting = members.get(0);
        String id = submit(accepting);
        Await.until("a few tiles", WAIT_MILLIS, () -> accepting.jobs.status(id).progress() > 0.05);
        SealedMap<String, JobRecord> table = members.get(1).data.jobs();
        members.get(1).hazelcast.getMap(ClusterMaps.IMAGES).addInterceptor(new SlowPut(1_000));

        accepting.kill();

        Await.until("another member to take the job over", WAIT_MILLIS,
                () -> !table.get(id).owner().equals(accepting.uuid));
        String owner = table.get(id).owner();
        TestMember taker = members.get(1).uuid.equals(owner) ? members.get(1) : members.get(2);
        TestMember other = taker == members.get(1) ? members.get(2) : members.get(1);
        Await.until("the job to end through either member", WAIT_MILLIS,
                () -> taker.jobs.status(id).state().isFinal() || other.jobs.status(id).state().isFinal());
        assertThat(taker.jobs.image(id).bytes()).isEqualTo(oneMachine);
        assertThat(other.jobs.image(id).bytes()).isEqualTo(oneMachine);
        assertThat(awaitFinal(taker, id).state()).isEqualTo(JobState.DONE);
        assertThat(other.jobs.status(id).state()).isEqualTo(JobState.DONE);
    }

    /**
     * The outcome of a graceful leave: the job ends done with one machine's bytes. It does not tell
     * the worker's hand-back from the owner re-queueing a departed member's tiles (it passes without
     * the hand-back too); a test of the hand-back itself would watch the queue while the member drains.
     */
    @Test
    void aWorkerLeavingGracefullyLosesNoTile() throws Exception {
        start(2);
        TestMember accepting = members.get(0), worker = members.get(1);
        String id = submit(accepting);
        Await.until("the worker to render a tile", WAIT_MILLIS, () -> tilesOf(accepting.jobs.status(id), worker) > 0);

        worker.close();

        assertThat(awaitFinal(accepting, id).state()).isEqualTo(JobState.DONE);
        assertThat(accepting.jobs.image(id).bytes()).isEqualTo(oneMachine);
    }

    @Test
    void aTileThatKeepsFailingFailsTheJobNamingTheTile() throws Exception {
        start(2);
        String id = submit(members.get(0));
        Await.until("the job to run", WAIT_MILLIS, () -> members.get(0).jobs.status(id).state() == JobState.RUNNING);

        // the last tile, rendered last, fails at its last attempt as a worker reports it
        int last = TILES - 1;
        members.get(1).data.tiles(id).set(last,
                TileResult.failed(new TileTask(id, last, TileFarm.MAX_ATTEMPTS - 1), "test", "a worker failed"));

        JobStatus end = awaitFinal(members.get(1), id);
        assertThat(end.state()).isEqualTo(JobState.FAILED);
        assertThat(end.error()).isEqualTo("the tile at 128,96 failed 3 times; the last time: a worker failed");
    }

    @Test
    void aTileWhoseResultIsLostIsRenderedAgain() throws Exception {
        start(2);
        String id = submit(members.get(0));
        // the last tile, rendered last: its first result put fails, as one may while partitions move
        members.get(1).hazelcast.<Integer, byte[]>getMap(ClusterMaps.tiles(id))
                .addInterceptor(new FirstPutFails(id, TILES - 1));

        JobStatus end = awaitFinal(members.get(1), id);

        assertThat(end.state()).isEqualTo(JobState.DONE);
        assertThat(FirstPutFails.failed).contains(id);
        assertThat(members.get(1).jobs.image(id).bytes()).isEqualTo(oneMachine);
    }

    /** A map interceptor that changes nothing but what it overrides (the members share this JVM). */
    interface PassThrough extends MapInterceptor {

        @Override
        default Object interceptGet(Object value) {
            return value;
        }

        @Override
        default void afterGet(Object value) {
        }

        @Override
        default Object interceptPut(Object oldValue, Object newValue) {
            return newValue;
        }

        @Override
        default void afterPut(Object value) {
        }

        @Override
        default Object interceptRemove(Object removedValue) {
            return removedValue;
        }

        @Override
        default void afterRemove(Object value) {
        }
    }

    /** Fails the first put of one tile's result (the static record of it: the members share this JVM). */
    record FirstPutFails(String jobId, int index) implements PassThrough {

        static final Set<String> failed = ConcurrentHashMap.newKeySet();

        @Override
        public Object interceptPut(Object oldValue, Object newValue) {
            if (newValue instanceof byte[] sealed && isResultOfTheTile(sealed) && failed.add(jobId)) {
                throw new IllegalStateException("the put was lost");
            }
            return newValue;
        }

        /** A rendered result of the tile: it opens as the entry of that tile's index. */
        private boolean isResultOfTheTile(byte[] sealed) {
            byte[] plain = SEAL.open(ClusterMaps.TILES_FAMILY, ClusterMaps.tiles(jobId), index, sealed);
            try {
                return plain != null && ClusterCodecs.TILE_RESULT.decode(plain).rgb() != null;
            } catch (java.io.IOException e) {
                return false;
            }
        }
    }

    private static final Seal SEAL = TestMember.seal();

    /** Holds up every put before it is made (on the member that holds the entry). */
    record SlowPut(long millis) implements PassThrough {

        @Override
        public Object interceptPut(Object oldValue, Object newValue) {
            pause(millis);
            return newValue;
        }
    }

    private static void pause(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static JobListener recorder(List<Object> events) {
        return recorder(events, new AtomicInteger());
    }

    /** Records status, tile and end events in order, and counts heartbeats apart. */
    private static JobListener recorder(List<Object> events, AtomicInteger heartbeats) {
        return new JobListener() {
            @Override
            public void heartbeat() {
                heartbeats.incrementAndGet();
            }

            @Override
            public void status(JobStatus status) {
                events.add(status);
            }

            @Override
            public void tile(TileEvent tile) {
                events.add(tile);
            }

            @Override
            public void end(JobStatus status) {
                events.add("end " + status.state().json());
            }
        };
    }
}

package studio.server.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import com.hazelcast.core.HazelcastInstance;
import com.hazelcast.instance.impl.HazelcastInstanceProxy;
import com.hazelcast.map.IMap;
import com.hazelcast.map.impl.MapService;
import com.hazelcast.map.listener.EntryRemovedListener;
import com.hazelcast.spi.impl.eventservice.EventRegistration;

import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.server.Await;
import studio.server.job.JobRequests;
import studio.server.job.JobState;
import studio.server.job.JobStatus;
import studio.server.render.ImageFiles;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.SceneCompiler;

/**
 * A worker keeps its claim once its tile's result is in the tile map (deleting it cost two of a tile's
 * round trips), and a coordinator that hears none of its results' events (as while partitions move)
 * still finds every result, claimed or not, at its looks for lost tiles, and those of a worker that
 * died after putting them: the job ends done with one machine's bytes.
 */
class ClusterClaimsTest {

    private static byte[] oneMachine;

    private final List<TestMember> members = new ArrayList<>();
    private final String name = "test-" + UUID.randomUUID();

    @BeforeAll
    static void renderOnOneMachine() {
        CompiledScene scene = compile();
        oneMachine = ImageFiles.encode(Renderer.render(RenderRequest.of(scene.scene(), scene.settings())).film(),
                scene.format(), scene.quality());
    }

    @AfterEach
    void stopMembers() {
        for (TestMember member : members) {
            member.kill();
        }
    }

    @Test
    void aJobWhoseResultEventsAreAllLostEndsDoneAndItsClaimsStay() throws Exception {
        start();
        TestMember owner = members.get(0);
        String id = submitDeaf(owner);
        AtomicInteger claimsDeleted = new AtomicInteger();
        owner.hazelcast.getMap(ClusterMaps.claims(id))
                .addEntryListener((EntryRemovedListener<Object, Object>) event -> claimsDeleted.incrementAndGet(), false);
        deaf.countDown();

        JobStatus end = awaitDone(owner, id);
        assertThat(end.workers().values().stream().mapToInt(Integer::intValue).sum()).isEqualTo(ClusterJobsTest.TILES);
        assertThat(claimsDeleted).as("claims deleted while the job ran").hasValue(0);
    }

    /** A worker that dies after putting results (its claims kept): its tiles are assembled, not rendered again. */
    @Test
    void theTilesOfAWorkerThatDiedAfterPuttingThemAreNotRenderedAgain() throws Exception {
        start();
        TestMember owner = members.get(0), worker = members.get(1);
        String id = submitDeaf(owner);
        deaf.countDown();
        Await.until("the worker to put a few results", ClusterJobsTest.WAIT_MILLIS,
                () -> owner.data.tiles(id).values().stream().filter(result -> result.worker().equals(worker.address))
                        .count() >= 2);

        worker.kill();

        JobStatus end = awaitDone(owner, id);
        assertThat(end.workers().getOrDefault(worker.address, 0)).as("tiles of the dead worker assembled")
                .isGreaterThanOrEqualTo(2);
    }

    private final CountDownLatch deaf = new CountDownLatch(1);

    private void start() throws Exception {
        int[] ports = {TestMember.BASE_PORT, TestMember.BASE_PORT + 1};
        for (int port : ports) {
            members.add(new TestMember(name, port, ports));
        }
        Await.until("the cluster to be safe", ClusterJobsTest.WAIT_MILLIS,
                () -> members.stream().allMatch(member -> member.hazelcast.getPartitionService().isClusterSafe()));
    }

    /**
     * Submits the test scene to {@code owner} and stops its coordinator hearing its results' events; the
     * workers take no tile until {@link #deaf} is counted down.
     */
    private String submitDeaf(TestMember owner) throws Exception {
        for (TestMember member : members) {
            member.onTaken = task -> awaitQuietly(deaf);
        }
        byte[] json = ClusterJobsTest.SCENE.getBytes(StandardCharsets.UTF_8);
        String id = owner.jobs.submit(JobRequests.of(compile(), json)).id();
        String tiles = ClusterMaps.tiles(id);
        Await.until("the coordinator to listen for results", ClusterJobsTest.WAIT_MILLIS,
                () -> !registrations(owner.hazelcast, tiles).isEmpty());
        IMap<Object, Object> results = owner.hazelcast.getMap(tiles);
        for (EventRegistration registration : registrations(owner.hazelcast, tiles)) {
            results.removeEntryListener(registration.getId());
        }
        return id;
    }

    private static JobStatus awaitDone(TestMember owner, String id) throws Exception {
        Await.until("job " + id + " to end", ClusterJobsTest.WAIT_MILLIS, () -> owner.jobs.status(id).state().isFinal());
        JobStatus end = owner.jobs.status(id);
        assertThat(end.state()).isEqualTo(JobState.DONE);
        assertThat(owner.jobs.image(id).bytes()).isEqualTo(oneMachine);
        return end;
    }

    private static Collection<EventRegistration> registrations(HazelcastInstance member, String map) {
        return ((HazelcastInstanceProxy) member).getOriginal().node.getNodeEngine().getEventService()
                .getRegistrations(MapService.SERVICE_NAME, map);
    }

    private static CompiledScene compile() {
        return SceneCompiler.standalone(TestMember.VALIDATION::getValidator)
                .compile(CompileRequest.of(ClusterJobsTest.SCENE.getBytes(StandardCharsets.UTF_8)));
    }

    private static void awaitQuietly(CountDownLatch latch) {
        try {
            latch.await(ClusterJobsTest.WAIT_MILLIS, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}

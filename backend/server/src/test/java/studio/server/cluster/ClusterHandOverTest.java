package studio.server.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Executors;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

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
 * A member told to stop (SIGTERM) hands its jobs to the others at once, and leaves as soon as they
 * have them: the jobs end done with one machine's bytes, and their event streams through another
 * member go on to the end, without a cancel.
 */
class ClusterHandOverTest {

    private static final int P = TestMember.BASE_PORT;
    private static final long GRACE_MILLIS = 20_000;
    /** The glass scene of ClusterJobsTest at four times the samples: still running when its owner stops. */
    private static final String SCENE = ClusterJobsTest.SCENE.replace("\"samples\": 24", "\"samples\": 96");
    private static byte[] oneMachine;
    private final List<TestMember> members = new ArrayList<>();
    private final String name = "handover-" + UUID.randomUUID();

    @BeforeAll
    static void renderOnOneMachine() {
        CompiledScene scene = SceneCompiler.standalone(TestMember.VALIDATION::getValidator)
                .compile(CompileRequest.of(SCENE.getBytes(StandardCharsets.UTF_8)));
        oneMachine = ImageFiles.encode(Renderer.render(RenderRequest.of(scene.scene(), scene.settings())).film(), scene.format(),
                scene.quality());
    }

    @AfterEach
    void stopMembers() {
        members.forEach(TestMember::kill);
    }

    private String submit(TestMember member) {
        byte[] json = SCENE.getBytes(StandardCharsets.UTF_8);
        CompiledScene scene = SceneCompiler.standalone(TestMember.VALIDATION::getValidator).compile(CompileRequest.of(json));
        return member.jobs.submit(JobRequests.of(scene, json)).id();
    }

    @Test
    void aStoppingMemberHandsItsRunningAndQueuedJobsOverAtOnce() throws Exception {
        for (int i = 0; i < 3; i++) {
            members.add(new TestMember(name, P + i, P, P + 1, P + 2));
        }
        Await.until("the cluster to be safe", ClusterJobsTest.WAIT_MILLIS,
                () -> members.stream().allMatch(member -> member.hazelcast.getPartitionService().isClusterSafe()));
        TestMember stopping = members.get(0), reader = members.get(1);
        String running = submit(stopping), queued = submit(stopping); // one job at a time per member: one queued
        Await.until("a few tiles", ClusterJobsTest.WAIT_MILLIS, () -> stopping.jobs.status(running).progress() > 0.1);
        assertThat(stopping.jobs.status(queued).state()).isEqualTo(JobState.QUEUED);
        List<Object> events = new CopyOnWriteArrayList<>();
        assertThat(reader.cluster.subscribe(running, "", recorder(events), Executors.newSingleThreadExecutor())).isTrue();

        long start = System.nanoTime();
        stopping.stop(GRACE_MILLIS);
        long stoppedMillis = (System.nanoTime() - start) / 1_000_000;

        assertThat(stoppedMillis).as("handed over, not drained").isLessThan(GRACE_MILLIS / 2);
        assertThat(reader.data.jobs().get(running).owner()).isNotEqualTo(stopping.uuid);
        for (String id : List.of(running, queued)) {
            Await.until("job " + id + " to end", ClusterJobsTest.WAIT_MILLIS,
                    () -> reader.jobs.status(id).state().isFinal());
            assertThat(reader.jobs.status(id).state()).isEqualTo(JobState.DONE);
            assertThat(reader.jobs.image(id).bytes()).isEqualTo(oneMachine);
            assertThat(members.get(2).jobs.image(id).bytes()).isEqualTo(oneMachine);
        }
        Await.until("the stream through another member to end", ClusterJobsTest.WAIT_MILLIS,
                () -> !events.isEmpty() && events.get(events.size() - 1) instanceof String);
        assertThat(events.get(events.size() - 1)).isEqualTo("end done");
        assertThat(events).noneMatch(event -> event instanceof JobStatus status && status.state() == JobState.CANCELLED);
        assertThat(events.stream().filter(TileEvent.class::isInstance)).hasSize(ClusterJobsTest.TILES);
    }

    private static JobListener recorder(List<Object> events) {
        return new JobListener() {
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

            @Override
            public void dropped() {
                events.add("dropped");
            }
        };
    }
}

package studio.server.cluster;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.Executors;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import studio.server.Await;
import studio.server.job.JobRequests;
import studio.server.job.JobListener;
import studio.server.job.JobNotFoundException;
import studio.server.job.JobOwner;
import studio.server.job.JobState;
import studio.server.job.JobStatus;
import studio.server.job.TileEvent;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;

/**
 * With sign-in on, a job belongs to its principal cluster-wide: any member serves it to them, and to
 * nobody else, also after another member took it over from the one that accepted it.
 */
class ClusterJobOwnershipTest {

    private final List<TestMember> members = new ArrayList<>();
    private final String name = "test-" + UUID.randomUUID();

    @AfterEach
    void stopMembers() {
        members.forEach(TestMember::kill);
    }

    private void start(int count) throws Exception {
        int[] ports = new int[count];
        for (int i = 0; i < count; i++) {
            ports[i] = TestMember.BASE_PORT + i;
        }
        for (int port : ports) {
            members.add(new TestMember(name, port, ports));
        }
        Await.until("the cluster to be safe", ClusterJobsTest.WAIT_MILLIS,
                () -> members.stream().allMatch(member -> member.hazelcast.getPartitionService().isClusterSafe()));
    }

    private static String submitAsAlice(TestMember member) {
        byte[] json = ClusterJobsTest.SCENE.getBytes(StandardCharsets.UTF_8);
        CompiledScene scene = SceneCompiler.standalone(TestMember.VALIDATION::getValidator).compile(CompileRequest.of(json));
        return member.jobs.submit(JobRequests.of(scene, json, new JobOwner("alice", 4))).id();
    }

    private static final JobListener NOBODY = new JobListener() {
        @Override
        public void status(JobStatus status) {
        }

        @Override
        public void tile(TileEvent tile) {
        }

        @Override
        public void end(JobStatus status) {
        }
    };

    @Test
    void anotherMemberServesAJobToItsPrincipalOnly() throws Exception {
        start(2);
        TestMember accepting = members.get(0), other = members.get(1);
        String id = submitAsAlice(accepting);

        assertThat(other.jobs.status(id, "alice").id()).isEqualTo(id);
        assertThrows(JobNotFoundException.class, () -> other.jobs.status(id, "bob"));
        assertThrows(JobNotFoundException.class, () -> other.jobs.status(id, ""));
        assertThrows(JobNotFoundException.class, () -> other.jobs.cancel(id, "bob"));
        assertThat(other.cluster.subscribe(id, "bob", NOBODY, Executors.newSingleThreadExecutor())).isFalse();
        assertThat(other.cluster.image(id, "bob")).isNull();

        Await.until("the job's end", ClusterJobsTest.WAIT_MILLIS,
                () -> other.jobs.status(id, "alice").state().isFinal());
        assertThat(other.jobs.status(id, "alice").state()).as("bob's cancel did nothing").isEqualTo(JobState.DONE);
        assertThat(other.jobs.image(id, "alice").bytes()).isNotEmpty();
        assertThrows(JobNotFoundException.class, () -> other.jobs.image(id, "bob"));
        assertThrows(JobNotFoundException.class, () -> accepting.jobs.image(id, "bob"));
    }

    @Test
    void jobTakenOverStillBelongsToItsPrincipal() throws Exception {
        start(2);
        TestMember accepting = members.get(0), heir = members.get(1);
        String id = submitAsAlice(accepting);
        Await.until("a few tiles", ClusterJobsTest.WAIT_MILLIS, () -> accepting.jobs.status(id, "alice").progress() > 0.05);

        accepting.kill();

        Await.until("the job's end", ClusterJobsTest.WAIT_MILLIS, () -> heir.jobs.status(id, "alice").state().isFinal());
        assertThat(heir.jobs.status(id, "alice").state()).isEqualTo(JobState.DONE);
        assertThrows(JobNotFoundException.class, () -> heir.jobs.status(id, "bob"));
        assertThrows(JobNotFoundException.class, () -> heir.jobs.image(id, "bob"));
    }
}

package studio.server.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import com.hazelcast.map.IMap;

import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.server.Await;
import studio.server.job.JobRequests;
import studio.server.job.JobState;
import studio.server.job.JobStatus;
import studio.server.render.ImageFiles;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.SceneCompiler;

/**
 * Nothing read from the cluster is used before its seal is checked: values written into a running
 * job's structures without the cluster's secret (or replayed under another key, or sealed but of the
 * wrong size) are dropped and counted, and the job ends done with one machine's bytes.
 */
class ClusterSealTest {

    private static byte[] oneMachine;
    private final List<TestMember> members = new ArrayList<>();
    /** The first of the ports this JVM's test members use. */
    private static final int P = TestMember.BASE_PORT;
    private final String name = "seal-" + UUID.randomUUID();

    @BeforeAll
    static void renderOnOneMachine() {
        CompiledScene scene = SceneCompiler.standalone(TestMember.VALIDATION::getValidator)
                .compile(CompileRequest.of(ClusterJobsTest.SCENE.getBytes(StandardCharsets.UTF_8)));
        oneMachine = ImageFiles.encode(Renderer.render(RenderRequest.of(scene.scene(), scene.settings())).film(), scene.format(),
                scene.quality());
    }

    @AfterEach
    void stopMembers() {
        members.forEach(TestMember::kill);
    }

    @Test
    void forgedTileResultsAndCancelsAreDroppedCountedAndTheImageIsUnaffected() throws Exception {
        members.add(new TestMember(name, P, P, P + 1));
        members.add(new TestMember(name, P + 1, P, P + 1));
        TestMember owner = members.get(0), other = members.get(1);
        byte[] json = ClusterJobsTest.SCENE.getBytes(StandardCharsets.UTF_8);
        CompiledScene scene = SceneCompiler.standalone(TestMember.VALIDATION::getValidator).compile(CompileRequest.of(json));
        String id = owner.jobs.submit(JobRequests.of(scene, json)).id();
        Await.until("the job to run", ClusterJobsTest.WAIT_MILLIS,
                () -> owner.jobs.status(id).state() == JobState.RUNNING);

        // written straight into the cluster's maps, as any process that joined it could
        IMap<Integer, byte[]> tiles = other.hazelcast.getMap(ClusterMaps.tiles(id));
        int tileCount = ClusterJobsTest.TILES;
        double[] magenta = new double[3 * 32 * 32];
        for (int i = 0; i < magenta.length; i += 3) {
            magenta[i] = 1;
            magenta[i + 2] = 1;
        }
        for (int i = 0; i < tileCount; i++) {
            TileResult forged = new TileResult(i, 0, magenta, 1, 1, 0, "outsider", null);
            tiles.set(i, ClusterCodecs.TILE_RESULT.encode(forged)); // no seal at all
        }
        // sealed by a member, but replayed under another tile's key, or of the wrong size, or not finite
        SealedMap<Integer, TileResult> sealed = other.data.tiles(id);
        tiles.set(tileCount - 1, sealed.seal(0, new TileResult(tileCount - 1, 0, magenta, 1, 1, 0, "insider", null)));
        sealed.set(tileCount - 2, new TileResult(tileCount - 2, 0, new double[3], 1, 1, 0, "insider", null));
        double[] notFinite = magenta.clone();
        notFinite[7] = Double.NaN;
        sealed.set(tileCount - 3, new TileResult(tileCount - 3, 0, notFinite, 1, 1, 0, "insider", null));
        other.hazelcast.<String, byte[]>getMap(ClusterMaps.CANCELS).set(id, "cancelled".getBytes(StandardCharsets.UTF_8));

        Await.until("job " + id + " to end", ClusterJobsTest.WAIT_MILLIS,
                () -> other.jobs.status(id).state().isFinal());
        JobStatus end = other.jobs.status(id);
        assertThat(end.state()).isEqualTo(JobState.DONE);
        assertThat(other.jobs.image(id).bytes()).isEqualTo(oneMachine);
        assertThat(owner.jobs.image(id).bytes()).isEqualTo(oneMachine);
        // a forged value a genuine result overwrote before anyone read it is never seen: count those that were
        assertThat(owner.rejected(ClusterMaps.TILES_FAMILY) + other.rejected(ClusterMaps.TILES_FAMILY))
                .isGreaterThanOrEqualTo(1);
        assertThat(owner.rejected(ClusterMaps.CANCELS)).isGreaterThanOrEqualTo(1);
    }

    @Test
    void aValueThatDoesNotOpenReadsAsAbsent() throws Exception {
        members.add(new TestMember(name, P, P));
        TestMember member = members.get(0);
        member.hazelcast.<String, byte[]>getMap(ClusterMaps.JOBS).set("forged", "{\"state\":\"done\"}".getBytes(StandardCharsets.UTF_8));
        member.hazelcast.<String, byte[]>getMap(ClusterMaps.IMAGES).set("forged", new byte[] {(byte) 0x89, 'P', 'N', 'G'});

        assertThat(member.cluster.status("forged", "")).isNull();
        assertThat(member.cluster.image("forged", "")).isNull(); // refused at its record, which does not open
        assertThat(member.data.images().get("forged")).isNull();
        // (the job table is read in the background too, looking for jobs to take over)
        assertThat(member.rejected(ClusterMaps.JOBS)).isGreaterThanOrEqualTo(1);
        assertThat(member.rejected(ClusterMaps.IMAGES)).isEqualTo(1);
    }
}

package studio.server.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

import io.micrometer.core.instrument.simple.SimpleMeterRegistry;
import studio.server.job.JobState;
import studio.server.job.JobStatus;
import studio.server.job.TileEvent;

/** A sealed value opens only with the secret, in the structure and under the key it was sealed for. */
class SealTest {

    private final SimpleMeterRegistry registry = new SimpleMeterRegistry();
    private final Seal seal = new Seal(secret(TestMember.SECRET), registry);
    private final byte[] plain = "a tile's pixels".getBytes(StandardCharsets.UTF_8);

    private static ClusterSecret secret(String secret) {
        return ClusterSecret.of(new ClusterProperties(5701, List.of("a:5701"), "n", "", secret));
    }

    private double rejected(String family) {
        var counter = registry.find("studio.cluster.rejected").tag("structure", family).counter();
        return counter == null ? 0 : counter.count();
    }

    @Test
    void opensWhatItSealed() {
        byte[] sealed = seal.seal("studio-tiles", "studio-tiles-j1", 3, plain);
        assertThat(new String(sealed, StandardCharsets.ISO_8859_1)).doesNotContain("pixels");
        assertThat(seal.open("studio-tiles", "studio-tiles-j1", 3, sealed)).isEqualTo(plain);
        assertThat(rejected("studio-tiles")).isZero();
    }

    @Test
    void theWarmUpRejectsNothingAndItsValuesOpenNowhereElse() {
        seal.warmUp(3, 1_000);
        assertThat(rejected(Seal.WARM_UP)).isZero();
        byte[] warm = seal.seal(Seal.WARM_UP, Seal.WARM_UP, 0, plain);
        assertThat(seal.open("studio-tiles", Seal.WARM_UP, 0, warm)).isNull();
        byte[] sealed = seal.seal("studio-tiles", "studio-tiles-j1", 3, plain);
        assertThat(seal.open("studio-tiles", "studio-tiles-j1", 3, sealed)).isEqualTo(plain);
    }

    @Test
    void aValueReplayedUnderAnotherKeyOrJobDoesNotOpenAndIsCounted() {
        byte[] sealed = seal.seal("studio-tiles", "studio-tiles-j1", 3, plain);
        assertThat(seal.open("studio-tiles", "studio-tiles-j1", 4, sealed)).isNull();
        assertThat(seal.open("studio-tiles", "studio-tiles-j2", 3, sealed)).isNull();
        assertThat(seal.open("studio-claims", "studio-tiles-j1", 3, sealed)).isNull();
        assertThat(rejected("studio-tiles")).isEqualTo(2);
        assertThat(rejected("studio-claims")).isEqualTo(1);
    }

    @Test
    void threadsSealAndOpenAtOnceAndAValueThatDidNotOpenSpoilsNothing() throws Exception {
        ExecutorService threads = Executors.newFixedThreadPool(4);
        try {
            List<Future<Integer>> done = new ArrayList<>();
            for (int t = 0; t < 4; t++) {
                int thread = t;
                done.add(threads.submit(() -> {
                    int opened = 0;
                    for (int i = 0; i < 2_000; i++) {
                        byte[] value = ("tile " + thread + "/" + i).getBytes(StandardCharsets.UTF_8);
                        byte[] sealed = seal.seal("studio-tiles", "studio-tiles-j" + thread, i, value);
                        if (i % 7 == 0) {
                            byte[] tampered = sealed.clone();
                            tampered[tampered.length - 1] ^= 1;
                            assertThat(seal.open("studio-tiles", "studio-tiles-j" + thread, i, tampered)).isNull();
                        }
                        if (Arrays.equals(seal.open("studio-tiles", "studio-tiles-j" + thread, i, sealed), value)) {
                            opened++;
                        }
                    }
                    return opened;
                }));
            }
            for (Future<Integer> each : done) {
                assertThat(each.get(60, TimeUnit.SECONDS)).isEqualTo(2_000);
            }
        } finally {
            threads.shutdownNow();
        }
        assertThat(rejected("studio-tiles")).isEqualTo(4 * 286);
    }

    @Test
    void aValueOfAnotherSecretForgedOrTamperedDoesNotOpen() {
        Seal other = new Seal(secret("another cluster's secret, 32 bytes or more"), new SimpleMeterRegistry());
        assertThat(seal.open("studio-jobs", "studio-jobs", "j", other.seal("studio-jobs", "studio-jobs", "j", plain)))
                .isNull();
        byte[] sealed = seal.seal("studio-jobs", "studio-jobs", "j", plain);
        sealed[sealed.length / 2] ^= 1;
        assertThat(seal.open("studio-jobs", "studio-jobs", "j", sealed)).isNull();
        assertThat(seal.open("studio-jobs", "studio-jobs", "j", plain)).isNull();
        assertThat(seal.open("studio-jobs", "studio-jobs", "j", new byte[0])).isNull();
        assertThat(rejected("studio-jobs")).isEqualTo(4);
    }

    @Test
    void membersOfAnotherSecretFormAnotherCluster() {
        assertThat(secret(TestMember.SECRET).clusterName("ray-studio"))
                .isEqualTo(secret(TestMember.SECRET).clusterName("ray-studio"))
                .startsWith("ray-studio-")
                .isNotEqualTo(secret("another cluster's secret, 32 bytes or more").clusterName("ray-studio"));
    }

    @Test
    void theCodecsGiveBackWhatTheyWrote() throws Exception {
        JobStatus status = new JobStatus("j", JobState.RUNNING, 0.5, 1200, null, 160, 120, "a.png", "image/png", null,
                Map.of("127.0.0.1:5701", 3));
        JobRecord job = new JobRecord(status, "owner", 32, "");
        assertThat(ClusterCodecs.JOB_RECORD.decode(ClusterCodecs.JOB_RECORD.encode(job))).isEqualTo(job);
        TileEvent tile = new TileEvent(32, 64, 32, 32, "iVBORw0KGgo=", 0.25);
        assertThat(ClusterCodecs.EVENT.decode(ClusterCodecs.EVENT.encode(tile))).isEqualTo(tile);
        assertThat(ClusterCodecs.EVENT.decode(ClusterCodecs.EVENT.encode(status))).isEqualTo(status);
        TileResult result = new TileResult(2, 1, new double[] {0.25, 1, 2}, 10, 20, 0, "127.0.0.1:5701", null);
        TileResult back = ClusterCodecs.TILE_RESULT.decode(ClusterCodecs.TILE_RESULT.encode(result));
        assertThat(back.rgb()).containsExactly(0.25, 1, 2);
        assertThat(back.index()).isEqualTo(2);
        assertThat(back.worker()).isEqualTo("127.0.0.1:5701");
        TileTask task = new TileTask("j", 7, 2);
        assertThat(ClusterCodecs.TILE_TASK.decode(ClusterCodecs.TILE_TASK.encode(task))).isEqualTo(task);
    }
}

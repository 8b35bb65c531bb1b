package studio.server.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import com.hazelcast.collection.ItemEvent;
import com.hazelcast.collection.ItemListener;
import com.hazelcast.config.Config;
import com.hazelcast.config.MapConfig;
import com.hazelcast.core.DistributedObject;

import studio.engine.render.TileRect;
import studio.server.Await;
import studio.server.system.MemoryBudget;

/**
 * The start-up warm-up of a member's cluster path: a small scene's tiles through the member's own
 * structures, across the members (their partitions), touching none of the cluster's own (no task in
 * the tile queue, no job), rendered by this member's warm-up workers alone, every structure of it
 * gone afterwards, and stopped at its limit.
 */
class ClusterWarmUpTest {

    private final List<TestMember> members = new ArrayList<>();

    @AfterEach
    void stopMembers() {
        for (TestMember member : members) {
            member.kill();
        }
    }

    private void start() throws Exception {
        String name = "test-" + UUID.randomUUID();
        int[] ports = {TestMember.BASE_PORT + 2, TestMember.BASE_PORT + 3};
        for (int port : ports) {
            members.add(new TestMember(name, port, ports));
        }
        Await.until("the cluster to be safe", ClusterJobsTest.WAIT_MILLIS,
                () -> members.stream().allMatch(member -> member.hazelcast.getPartitionService().isClusterSafe()));
    }

    private ClusterWarmUp warmUp(TestMember member, Duration limit) {
        return new ClusterWarmUp(member.data, member.compiler, MemoryBudget.unlimited(), limit);
    }

    @Test
    void sendsEveryRoundsTilesThroughItsOwnStructuresAndLeavesNothing() throws Exception {
        start();
        AtomicInteger queued = new AtomicInteger();
        for (TestMember member : members) {
            member.hazelcast.getQueue(ClusterMaps.TILE_QUEUE).addItemListener(new ItemListener<Object>() {
                @Override
                public void itemAdded(ItemEvent<Object> item) {
                    queued.incrementAndGet();
                }

                @Override
                public void itemRemoved(ItemEvent<Object> item) {
                }
            }, false);
        }

        ClusterWarmUp.Outcome outcome = warmUp(members.get(0), Duration.ofMinutes(2)).run();

        int small = ClusterTiling.tiles(128, 128, ClusterWarmUp.TILE_SIZE).size();
        int full = ClusterTiling.tiles(ClusterWarmUp.FULL_SIZE, ClusterWarmUp.FULL_SIZE, ClusterJobs.LARGE_TILE).size();
        assertThat(outcome.rounds()).isEqualTo(1 + ClusterWarmUp.ROUNDS);
        assertThat(outcome.tiles()).isEqualTo(full + ClusterWarmUp.ROUNDS * small);
        assertThat(queued).as("tasks in the cluster's tile queue").hasValue(0);
        for (TestMember member : members) {
            assertThat(member.hazelcast.getDistributedObjects()).map(DistributedObject::getName)
                    .noneMatch(structure -> structure.contains("studio-warm-up-"));
            assertThat(member.data.jobs().keySet()).isEmpty();
            assertThat(member.rejected(ClusterMaps.TILES_FAMILY)).isZero();
        }
    }

    /** The full-size round is cut as a large job is: its results are a job's largest, and its smallest. */
    @Test
    void itsFullSizeRoundHasAJobsTileSizes() {
        List<TileRect> tiles = ClusterTiling.tiles(ClusterWarmUp.FULL_SIZE, ClusterWarmUp.FULL_SIZE,
                ClusterJobs.LARGE_TILE);

        assertThat(tiles).extracting(TileRect::width).containsOnly(2 * ClusterJobs.LARGE_TILE, ClusterJobs.LARGE_TILE);
        assertThat(tiles).extracting(TileRect::height).containsOnly(2 * ClusterJobs.LARGE_TILE, ClusterJobs.LARGE_TILE);
    }

    /** The warm-up's tile and claim maps and event log are configured as a job's, so it runs the code a job's run. */
    @Test
    void itsPerJobStructuresAreConfiguredAsAJobs() throws Exception {
        start();
        TestMember member = members.get(0);
        Config config = member.hazelcast.getConfig();
        ClusterData own = member.data.named("studio-warm-up-" + member.uuid + "-");

        MapConfig jobTiles = config.findMapConfig(member.data.tiles("a-job").name());
        assertThat(jobTiles.getTimeToLiveSeconds()).isEqualTo(MemberConfig.TILE_MAPS_TTL_SECONDS);
        assertThat(config.findMapConfig(own.tiles("warm-up-0").name()).getTimeToLiveSeconds())
                .isEqualTo(jobTiles.getTimeToLiveSeconds());
        assertThat(config.findMapConfig(own.claims("warm-up-0").name()).getTimeToLiveSeconds())
                .isEqualTo(config.findMapConfig(member.data.claims("a-job").name()).getTimeToLiveSeconds());
        assertThat(config.findRingbufferConfig(own.events("warm-up-0").name()).getCapacity())
                .isEqualTo(MemberConfig.EVENTS_CAPACITY);
    }

    @Test
    void stopsAtItsLimitAndLeavesNothing() throws Exception {
        start();

        long start = System.nanoTime();
        ClusterWarmUp.Outcome outcome = warmUp(members.get(0), Duration.ofMillis(1)).run();

        assertThat(outcome.rounds()).isZero();
        assertThat(outcome.tiles()).isZero();
        assertThat(System.nanoTime() - start).isLessThan(Duration.ofSeconds(10).toNanos());
        for (TestMember member : members) {
            assertThat(member.hazelcast.getDistributedObjects()).map(DistributedObject::getName)
                    .noneMatch(structure -> structure.contains("studio-warm-up-"));
        }
    }

    @Test
    void rendersNothingWhileOtherWorkHoldsTheRenderMemory() throws Exception {
        start();
        MemoryBudget memory = new MemoryBudget(64L << 20);
        try (MemoryBudget.Reservation taken = memory.tryReserve(memory.capacity())) {
            TestMember member = members.get(0);
            ClusterWarmUp.Outcome outcome = new ClusterWarmUp(member.data, member.compiler, memory,
                    Duration.ofMinutes(2)).run();

            assertThat(outcome.rounds()).as("rounds without the render memory reserved first").isZero();
            assertThat(outcome.tiles()).isZero();
        }
        assertThat(memory.reserved()).as("nothing left reserved").isZero();
        for (TestMember member : members) {
            assertThat(member.hazelcast.getDistributedObjects()).map(DistributedObject::getName)
                    .noneMatch(structure -> structure.contains("studio-warm-up-"));
        }
    }
}

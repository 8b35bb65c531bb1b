package studio.server.cluster;

import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.function.Consumer;

import com.hazelcast.core.Hazelcast;
import com.hazelcast.core.HazelcastInstance;

import jakarta.validation.Validation;
import jakarta.validation.ValidatorFactory;
import studio.server.job.JobService;
import studio.server.job.JobSettings;
import studio.server.render.RenderBudget;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.system.MemoryBudget;

/**
 * A member of a test cluster on loopback, wired as the application wires it (a Hazelcast member
 * from {@link MemberConfig}, its tile workers, the cluster's jobs and a job service), one worker
 * thread each so that the members share the machine's cores.
 */
final class TestMember implements AutoCloseable {

    static final ValidatorFactory VALIDATION = Validation.buildDefaultValidatorFactory();
    /** Streams of other members' jobs hear a heartbeat this often (5 s in the application). */
    static final long REMOTE_HEARTBEAT_MILLIS = 200;
    static final JobSettings SETTINGS = new JobSettings(1, 4, Duration.ofMinutes(10), 50, Duration.ofMinutes(10), 1);

    final int port;
    final HazelcastInstance hazelcast;
    final ClusterJobs cluster;
    final JobService jobs;
    final String address;
    /** The member's id, as the job table names a job's owner. */
    final String uuid;
    /** What the member's workers do once they took a tile from the queue, before they claim it. */
    volatile Consumer<TileTask> onTaken = task -> {
    };
    /** What the member's workers do once they claimed a tile they took, before they render it. */
    volatile Consumer<TileTask> onClaimed = task -> {
    };

    /** A member on 127.0.0.1:{@code port} of the cluster {@code name}, which lists the members on {@code ports}. */
    TestMember(String name, int port, int... ports) {
        this.port = port;
        List<String> members = Arrays.stream(ports).mapToObj(each -> "127.0.0.1:" + each).toList();
        hazelcast = Hazelcast.newHazelcastInstance(MemberConfig.of(new ClusterProperties(port, members, name, "127.0.0.1")));
        SceneCompiler compiler = SceneCompiler.standalone(VALIDATION::getValidator);
        TileWorkers workers = new TileWorkers(hazelcast,
                new JobScenes(hazelcast.getMap(ClusterMaps.SCENES), compiler, MemoryBudget.unlimited()), 1,
                new TileWorkers.Steps() {
                    @Override
                    public void taken(TileTask task) {
                        onTaken.accept(task);
                    }

                    @Override
                    public void claimed(TileTask task) {
                        onClaimed.accept(task);
                    }
                });
        cluster = new ClusterJobs(hazelcast, compiler, workers, 1, REMOTE_HEARTBEAT_MILLIS);
        jobs = new JobService(SETTINGS, RenderBudget.unlimited(), Duration.ofSeconds(2), cluster);
        address = ClusterNames.address(hazelcast.getCluster().getLocalMember());
        uuid = hazelcast.getCluster().getLocalMember().getUuid().toString();
    }

    /**
     * Dies as with SIGKILL, as far as the other members can tell, on the thread that calls it (one of
     * its own workers, say): its cluster member goes at once; the rest stops at {@link #kill}.
     */
    void die() {
        hazelcast.getLifecycleService().terminate();
    }

    /** Dies as with SIGKILL, as far as the other members can tell: it leaves without a word. */
    void kill() {
        hazelcast.getLifecycleService().terminate();
        cluster.close();
        jobs.shutdown(0);
    }

    /** Leaves as on SIGTERM: its jobs drain, its workers hand their tiles back, then the member leaves. */
    @Override
    public void close() {
        if (hazelcast.getLifecycleService().isRunning()) {
            jobs.shutdown(0);
            cluster.close();
            hazelcast.shutdown();
        }
    }
}

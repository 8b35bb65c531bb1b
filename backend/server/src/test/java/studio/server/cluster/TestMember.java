package studio.server.cluster;

import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.function.Consumer;

import com.hazelcast.config.Config;
import com.hazelcast.core.Hazelcast;
import com.hazelcast.core.HazelcastInstance;

import io.micrometer.core.instrument.simple.SimpleMeterRegistry;

import jakarta.validation.Validation;
import jakarta.validation.ValidatorFactory;
import studio.server.job.JobService;
import studio.server.job.JobSettings;
import studio.server.render.RenderBudget;
import studio.server.scene.compiling.MeshAssets;
import studio.server.scene.compiling.MeshCache;
import studio.server.scene.compiling.MeshFiles;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.compiling.SceneMapper;
import studio.server.scene.format.SceneLimits;
import studio.server.scene.reading.SceneReader;
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

    /** The first of four free ports on loopback, chosen once per JVM (another build may run its members beside). */
    static final int BASE_PORT = freePorts(4);

    /** The test clusters' secret. */
    static final String SECRET = "a test cluster's secret, 32 bytes or more";

    final int port;
    final HazelcastInstance hazelcast;
    /** The member's rejected values: studio.cluster.rejected. */
    final SimpleMeterRegistry registry = new SimpleMeterRegistry();
    final ClusterData data;
    final ClusterJobs cluster;
    final JobService jobs;
    final String address;
    /** The member's scene compiler, which reads meshes' assets from {@link #assets}. */
    final SceneCompiler compiler;
    /** Where the member's compiler reads meshes' assets (none unless a test gives it a store). */
    volatile MeshAssets assets = MeshAssets.none();
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
        ClusterProperties properties = properties(name, port, ports);
        Config config = MemberConfig.of(properties);
        // the map interceptors of ClusterJobsTest travel to the members by Java serialization: these alone
        config.getSerializationConfig().getJavaSerializationFilterConfig().getWhitelist()
                .addClasses(ClusterJobsTest.FirstPutFails.class.getName(), ClusterJobsTest.SlowPut.class.getName());
        hazelcast = Hazelcast.newHazelcastInstance(config);
        data = new ClusterData(hazelcast, new Seal(ClusterSecret.of(properties), registry));
        compiler = new SceneCompiler(SceneReader.forOneScene(VALIDATION::getValidator),
                new SceneMapper(SceneLimits.DEFAULTS, MeshCache.none(), new MeshAssets() {
                    @Override
                    public byte[] obj(String id) {
                        return assets.obj(id);
                    }

                    @Override
                    public byte[] gltf(String id) {
                        return assets.gltf(id);
                    }

                    @Override
                    public byte[] bytes(String id) {
                        return assets.bytes(id);
                    }
                }), MeshFiles.none());
        TileWorkers workers = new TileWorkers(data, new JobScenes(data.scenes(), compiler, MemoryBudget.unlimited()), 1,
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
        cluster = new ClusterJobs(compiler, workers, 1, REMOTE_HEARTBEAT_MILLIS);
        jobs = new JobService(SETTINGS, RenderBudget.unlimited(), Duration.ofSeconds(2), cluster);
        address = ClusterNames.address(hazelcast.getCluster().getLocalMember());
        uuid = hazelcast.getCluster().getLocalMember().getUuid().toString();
    }

    /** A member of the cluster {@code name} with the test secret on 127.0.0.1:{@code port}, listing {@code ports}. */
    static ClusterProperties properties(String name, int port, int... ports) {
        List<String> members = Arrays.stream(ports).mapToObj(each -> "127.0.0.1:" + each).toList();
        return new ClusterProperties(port, members, name, "127.0.0.1", SECRET);
    }

    /** What the test secret seals and opens (outside a member: interceptors, forgeries). */
    static Seal seal() {
        return new Seal(ClusterSecret.of(properties("any", 5701, 5701)), new SimpleMeterRegistry());
    }

    /** The values this member dropped from a structure family (studio.cluster.rejected). */
    double rejected(String family) {
        var counter = registry.find("studio.cluster.rejected").tag("structure", family).counter();
        return counter == null ? 0 : counter.count();
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

    /**
     * Stops as the application does on SIGTERM: the job service drains (in a cluster: hands its jobs to
     * the others, waiting at most {@code graceMillis} for them to take them), then the member leaves.
     */
    void stop(long graceMillis) {
        jobs.shutdown(graceMillis);
        cluster.close();
        hazelcast.shutdown();
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

    private static int freePorts(int count) {
        java.util.Random random = new java.util.Random();
        for (int attempt = 0; attempt < 100; attempt++) {
            int base = 20_000 + random.nextInt(30_000);
            boolean free = true;
            for (int port = base; port < base + count && free; port++) {
                try (java.net.ServerSocket socket = new java.net.ServerSocket(port, 1,
                        java.net.InetAddress.getLoopbackAddress())) {
                    socket.setReuseAddress(true);
                } catch (java.io.IOException e) {
                    free = false;
                }
            }
            if (free) {
                return base;
            }
        }
        throw new IllegalStateException("no " + count + " free ports on loopback");
    }
}

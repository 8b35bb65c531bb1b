package studio.bench.jmh;

import java.util.concurrent.TimeUnit;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

import studio.bench.MeshScene;
import studio.bench.ScalingScenes;
import studio.engine.accel.Traversal;
import studio.engine.accel.Walks;
import studio.engine.accel.WideBoxTests;
import studio.engine.accel.WideBvh;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Shape;
import studio.engine.geometry.TriangleMesh;
import studio.engine.scene.SceneObject;

/**
 * The engine's traversal ({@link Traversal}) walking the binary BVH against it walking the
 * eight-wide one ({@link WideBvh}) on the same leaves and rays: {@code spheres-10k}, the scaling
 * benchmark's 10,000 spheres, and {@code mesh-100k}, the 104,000-triangle torus knot, each through
 * the engine's own leaf tests, the same in every walk. Random rays as {@link BvhTraversalBenchmark}'s.
 * The forks run with the incubator module and {@code studio.vector=on}, so {@code wide} is the
 * Vector API walk on JDK 17 as on 25: {@code java -jar studio-bench.jar jmh WideBvhBenchmark}; the
 * scalar wide walk is {@link studio.bench.WideCommand}'s {@code wide-scalar}.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Fork(value = 1, jvmArgsAppend = {"--add-modules", "jdk.incubator.vector", "-Dstudio.vector=on"})
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 3, time = 1)
@State(Scope.Thread)
public class WideBvhBenchmark {

    @Param({"spheres-10k", "mesh-100k"})
    public String scene;

    @Param({"binary", "wide"})
    public String tree;

    private Walks walks;
    private Traversal walk;
    private Ray[] rays;
    private int next;

    @Setup
    public void setUp() {
        walks = walks(scene);
        walk = walk(walks, tree);
        rays = RandomRays.toward(walks.bounds(), 4);
    }

    /** The leaves and tree of a scene: {@code spheres-10k} or {@code mesh-100k}. */
    public static Walks walks(String scene) {
        if (scene.equals("spheres-10k")) {
            return Walks.ofShapes(ScalingScenes.spheres(10_000).stream().map(SceneObject::shape).toArray(Shape[]::new));
        }
        if (scene.equals("mesh-100k")) {
            TriangleMesh knot = ScalingScenes.placedKnot(MeshScene.mesh());
            return Walks.ofTriangles(knot.positions(), knot.indices());
        }
        throw new IllegalArgumentException(scene);
    }

    /**
     * The traversal walking the tree as named: {@code binary}, or {@code wide} with this JVM's box
     * test; {@code wide-scalar} and {@code wide-vector} are {@code wide} where that is this JVM's.
     */
    public static Traversal walk(Walks walks, String name) {
        boolean vector = WideBoxTests.vectorized();
        return switch (name) {
            case "binary" -> walks.binary();
            case "wide" -> walks.wide();
            case "wide-scalar", "wide-vector" -> {
                if (vector != name.equals("wide-vector")) {
                    throw new IllegalStateException(name + " needs " + WideBoxTests.PROPERTY + "="
                            + (vector ? "off" : "on") + ", this JVM's box test is " + WideBoxTests.get());
                }
                yield walks.wide();
            }
            default -> throw new IllegalArgumentException(name);
        };
    }

    @Benchmark
    public double closestHit() {
        return walks.nearest(walk, rays[next++ & RandomRays.MASK], Double.POSITIVE_INFINITY);
    }

    @Benchmark
    public boolean anyHit() {
        return walks.any(walk, rays[next++ & RandomRays.MASK], 1.0);
    }
}

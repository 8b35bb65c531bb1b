package studio.bench.jmh;

import java.util.List;
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
import studio.engine.accel.Aabb;
import studio.engine.accel.BinaryWalk;
import studio.engine.accel.Bvh;
import studio.engine.accel.Primitives;
import studio.engine.accel.ScalarBoxTest;
import studio.engine.accel.SpherePrimitives;
import studio.engine.accel.TrianglePrimitives;
import studio.engine.accel.WideBoxTests;
import studio.engine.accel.WideBvh;
import studio.engine.accel.WideWalk;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Sphere;
import studio.engine.geometry.TriangleMesh;
import studio.engine.scene.SceneObject;

/**
 * The binary BVH walk against the wide one ({@link WideBvh}) on the same primitives and rays,
 * the wide one with the scalar and with the Vector API box test: {@code spheres-10k}, the scaling
 * benchmark's 10,000 spheres, and {@code mesh-100k}, the 104,000-triangle torus knot (Möller-Trumbore
 * triangles, the same in every walk). Random rays as {@link BvhTraversalBenchmark}'s. The forks
 * run with the incubator module and {@code studio.vector=on}, so {@code wide-vector} is the Vector
 * API path on JDK 17 as on 25: {@code java -jar studio-bench.jar jmh WideBvhBenchmark}.
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

    @Param({"binary", "wide-scalar", "wide-vector"})
    public String tree;

    private BinaryWalk binary;
    private WideWalk wide;
    private Ray[] rays;
    private int next;

    @Setup
    public void setUp() {
        Primitives leaves = leaves(scene);
        Bvh bvh = Bvh.build(leaves.boxes(), leaves.count());
        switch (tree) {
            case "binary" -> binary = new BinaryWalk(bvh, leaves);
            case "wide-scalar" -> wide = new WideWalk(WideBvh.of(bvh), leaves, new ScalarBoxTest());
            case "wide-vector" -> {
                if (!WideBoxTests.vectorized()) {
                    throw new IllegalStateException("the Vector API box test is not in use");
                }
                wide = new WideWalk(WideBvh.of(bvh), leaves, WideBoxTests.get());
            }
            default -> throw new IllegalArgumentException(tree);
        }
        rays = RandomRays.toward(bounds(leaves.boxes()), 4);
    }

    /** The primitives of a scene: {@code spheres-10k} or {@code mesh-100k}. */
    public static Primitives leaves(String scene) {
        if (scene.equals("spheres-10k")) {
            List<SceneObject> objects = ScalingScenes.spheres(10_000);
            double[] spheres = new double[4 * objects.size()];
            for (int i = 0; i < objects.size(); i++) {
                Sphere s = (Sphere) objects.get(i).shape();
                spheres[4 * i] = s.center().x();
                spheres[4 * i + 1] = s.center().y();
                spheres[4 * i + 2] = s.center().z();
                spheres[4 * i + 3] = s.radius();
            }
            return new SpherePrimitives(spheres);
        }
        if (scene.equals("mesh-100k")) {
            TriangleMesh knot = ScalingScenes.placedKnot(MeshScene.mesh());
            return new TrianglePrimitives(knot.positions(), knot.indices());
        }
        throw new IllegalArgumentException(scene);
    }

    /** The union of primitive boxes (six doubles each). */
    public static Aabb bounds(double[] boxes) {
        double[] b = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE,
                -Double.MAX_VALUE};
        for (int i = 0; i < boxes.length; i += 6) {
            for (int a = 0; a < 3; a++) {
                b[a] = Math.min(b[a], boxes[i + a]);
                b[a + 3] = Math.max(b[a + 3], boxes[i + a + 3]);
            }
        }
        return new Aabb(b[0], b[1], b[2], b[3], b[4], b[5]);
    }

    @Benchmark
    public int closestHit() {
        Ray ray = rays[next++ & RandomRays.MASK];
        return binary != null ? binary.closest(ray, Double.POSITIVE_INFINITY) : wide.closest(ray, Double.POSITIVE_INFINITY);
    }

    @Benchmark
    public boolean anyHit() {
        Ray ray = rays[next++ & RandomRays.MASK];
        return binary != null ? binary.occluded(ray, 1.0) : wide.occluded(ray, 1.0);
    }
}

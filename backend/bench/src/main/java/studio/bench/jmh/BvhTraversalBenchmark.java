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
import org.openjdk.jmh.infra.Blackhole;

import studio.bench.MeshScene;
import studio.bench.ScalingScenes;
import studio.engine.accel.Aabb;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.TriangleMesh;
import studio.engine.scene.Scene;

/**
 * A whole scene's closest hit ({@link Scene#intersect}) and any-hit ({@link Scene#occluded}) through
 * its BVHs: {@code spheres-10k}, the scaling benchmark's 10,000 spheres (the scene's BVH over the
 * objects), and {@code mesh-100k}, the peer benchmark's 104,000-triangle torus knot (one object; the
 * mesh's BVH over its triangles). No ground plane. Random rays from all around toward points inside
 * the objects' bounds, cycling through a pre-generated array; any-hit ends at that point (t = 1).
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Fork(1)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 3, time = 1)
@State(Scope.Thread)
public class BvhTraversalBenchmark {

    @Param({"spheres-10k", "mesh-100k"})
    public String scene;

    private Scene world;
    private Ray[] rays;
    private final Hit hit = new Hit();
    private int next;

    @Setup
    public void setUp() {
        Aabb bounds;
        if (scene.equals("spheres-10k")) {
            world = ScalingScenes.scene(ScalingScenes.spheres(10_000));
            bounds = bounds(world);
        } else {
            TriangleMesh knot = ScalingScenes.placedKnot(MeshScene.mesh());
            world = ScalingScenes.scene(List.of(ScalingScenes.knotObject(knot)));
            bounds = knot.bounds();
        }
        rays = RandomRays.toward(bounds, 4);
    }

    /** The union of the scene's objects' bounds. */
    private static Aabb bounds(Scene s) {
        double[] b = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE,
                -Double.MAX_VALUE};
        for (int i = 0; i < s.objectCount(); i++) {
            Aabb a = s.shape(i).bounds();
            b[0] = Math.min(b[0], a.minX());
            b[1] = Math.min(b[1], a.minY());
            b[2] = Math.min(b[2], a.minZ());
            b[3] = Math.max(b[3], a.maxX());
            b[4] = Math.max(b[4], a.maxY());
            b[5] = Math.max(b[5], a.maxZ());
        }
        return new Aabb(b[0], b[1], b[2], b[3], b[4], b[5]);
    }

    @Benchmark
    public void closestHit(Blackhole bh) {
        bh.consume(world.intersect(rays[next++ & RandomRays.MASK], Double.POSITIVE_INFINITY, hit));
        bh.consume(hit.t);
    }

    @Benchmark
    public void anyHit(Blackhole bh) {
        bh.consume(world.occluded(rays[next++ & RandomRays.MASK], 1.0));
    }
}

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
import org.openjdk.jmh.infra.Blackhole;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.TriangleMesh;
import studio.engine.math.Vec3;
import studio.engine.mesh.MeshData;

/**
 * One ray against one triangle: a {@link TriangleMesh} of a single triangle, so each call is the
 * watertight test's per-ray set-up, one box test (the BVH's only node) and the triangle test, and
 * for a hit the barycentric point and normal ({@code flat}: geometric; {@code smooth}: interpolated
 * vertex normals). Random rays toward the triangle's bounds, from every side.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Fork(1)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 3, time = 1)
@State(Scope.Thread)
public class RayTriangleBenchmark {

    @Param({"flat", "smooth"})
    public String shading;

    private TriangleMesh triangle;
    private Ray[] rays;
    private final Hit hit = new Hit();
    private int next;

    @Setup
    public void setUp() {
        double[] positions = {-1, -0.8, 0.1, 1.2, -1, -0.2, 0.1, 1, 0.3};
        double[] normals = shading.equals("smooth") ? new double[] {-0.2, -0.1, 1, 0.2, -0.2, 1, 0, 0.2, 1} : null;
        triangle = new TriangleMesh(new MeshData(positions, new int[] {0, 1, 2}, normals), new Vec3(0.5, 1, -0.25), 1,
                new Vec3(10, 20, 30));
        rays = RandomRays.toward(triangle.bounds(), 3);
    }

    @Benchmark
    public void intersect(Blackhole bh) {
        bh.consume(triangle.intersect(rays[next++ & RandomRays.MASK], Double.POSITIVE_INFINITY, hit));
        bh.consume(hit.t);
    }

    @Benchmark
    public void occluded(Blackhole bh) {
        bh.consume(triangle.occluded(rays[next++ & RandomRays.MASK], 1.0));
    }
}

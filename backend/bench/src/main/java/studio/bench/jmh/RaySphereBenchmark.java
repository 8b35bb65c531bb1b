package studio.bench.jmh;

import java.util.concurrent.TimeUnit;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import org.openjdk.jmh.infra.Blackhole;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Sphere;
import studio.engine.math.Vec3;

/**
 * One ray against one sphere: the closest hit (which fills the {@link Hit}) and the any-hit test
 * of a shadow ray, on random rays toward the sphere's bounding box (about half of them hit).
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Fork(1)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 3, time = 1)
@State(Scope.Thread)
public class RaySphereBenchmark {

    private Sphere sphere;
    private Ray[] rays;
    private final Hit hit = new Hit();
    private int next;

    @Setup
    public void setUp() {
        sphere = new Sphere(new Vec3(0.5, 1, -0.25), 1.5);
        rays = RandomRays.toward(sphere.bounds(), 1);
    }

    @Benchmark
    public void intersect(Blackhole bh) {
        bh.consume(sphere.intersect(rays[next++ & RandomRays.MASK], Double.POSITIVE_INFINITY, hit));
        bh.consume(hit.t);
    }

    @Benchmark
    public void occluded(Blackhole bh) {
        bh.consume(sphere.occluded(rays[next++ & RandomRays.MASK], 1.0));
    }
}

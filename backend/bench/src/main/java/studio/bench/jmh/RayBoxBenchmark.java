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

import studio.engine.geometry.Box;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.math.Vec3;

/**
 * One ray against one box, axis-aligned or rotated about all three axes: closest hit and any-hit,
 * on random rays toward the box's bounds.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Fork(1)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 3, time = 1)
@State(Scope.Thread)
public class RayBoxBenchmark {

    @Param({"axis-aligned", "rotated"})
    public String orientation;

    private Box box;
    private Ray[] rays;
    private final Hit hit = new Hit();
    private int next;

    @Setup
    public void setUp() {
        Vec3 rotation = orientation.equals("rotated") ? new Vec3(30, 45, 60) : Vec3.ZERO;
        box = new Box(new Vec3(0.5, 1, -0.25), new Vec3(2.2, 0.9, 1.4), rotation);
        rays = RandomRays.toward(box.bounds(), 2);
    }

    @Benchmark
    public void intersect(Blackhole bh) {
        bh.consume(box.intersect(rays[next++ & RandomRays.MASK], Double.POSITIVE_INFINITY, hit));
        bh.consume(hit.t);
    }

    @Benchmark
    public void occluded(Blackhole bh) {
        bh.consume(box.occluded(rays[next++ & RandomRays.MASK], 1.0));
    }
}

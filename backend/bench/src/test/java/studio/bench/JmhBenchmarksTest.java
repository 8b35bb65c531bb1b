package studio.bench;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;

/**
 * JMH's annotation processor ran: META-INF/BenchmarkList (what {@code studio-bench.jar jmh} reads to
 * find the benchmarks) lists every benchmark class.
 */
class JmhBenchmarksTest {

    @Test
    void benchmarkListHasEveryBenchmark() throws Exception {
        String list;
        try (InputStream in = getClass().getClassLoader().getResourceAsStream("META-INF/BenchmarkList")) {
            assertNotNull(in, "META-INF/BenchmarkList is missing: the JMH annotation processor did not run");
            list = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        // one line per benchmark method: "JMH S <length> <class> S <length> <generated class> S <length> <method> ..."
        for (String benchmark : new String[] {"RaySphereBenchmark intersect", "RaySphereBenchmark occluded",
                "RayBoxBenchmark intersect", "RayBoxBenchmark occluded", "RayTriangleBenchmark intersect",
                "RayTriangleBenchmark occluded", "BvhTraversalBenchmark closestHit", "BvhTraversalBenchmark anyHit"}) {
            String[] classAndMethod = benchmark.split(" ");
            String userClass = " studio.bench.jmh." + classAndMethod[0] + " ";
            String method = " " + classAndMethod[1] + " ";
            assertTrue(list.lines().anyMatch(line -> line.contains(userClass) && line.contains(method)),
                    benchmark + " not in\n" + list);
        }
    }
}

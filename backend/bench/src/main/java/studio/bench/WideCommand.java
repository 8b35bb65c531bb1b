package studio.bench;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import studio.bench.jmh.RandomRays;
import studio.bench.jmh.WideBvhBenchmark;
import studio.engine.accel.Traversal;
import studio.engine.accel.WideBoxTests;
import studio.engine.accel.Walks;
import studio.engine.geometry.Ray;

/**
 * {@code java -jar studio-bench.jar wide [ROUNDS]}: the engine's traversal walking the binary BVH
 * against it walking the wide one, scalar and Vector API, in thread CPU time per ray (the machine
 * may be busy: CPU time counts only this thread's work). Each (scene, walk) runs in a process of
 * its own (so the JIT sees one walk), with the incubator module and {@code studio.vector} on, or
 * off for the scalar wide walk, twice in alternation; each process
 * measures ROUNDS rounds (default 6) of 8 x 16,384 random rays (those of {@link WideBvhBenchmark})
 * after two of warm-up; prints the median of the rounds in ns a ray.
 */
public final class WideCommand {

    private static final String[] SCENES = {"spheres-10k", "mesh-100k"};
    private static final String[] WALKS = {"binary", "wide-scalar", "wide-vector"};

    private WideCommand() {
    }

    public static int run(String[] args, PrintStream out, PrintStream err) throws Exception {
        if (args.length > 0 && args[0].equals("one")) {
            one(args[1], args[2], Integer.parseInt(args[3]), out);
            return 0;
        }
        int rounds = args.length > 0 ? Integer.parseInt(args[0]) : 6;
        String java = ProcessHandle.current().info().command().orElse("java");
        String classPath = System.getProperty("java.class.path");
        Map<String, List<Double>> results = new TreeMap<>();
        for (int alternation = 0; alternation < 2; alternation++) {
            for (String scene : SCENES) {
                for (String walk : WALKS) {
                    String vector = "-D" + WideBoxTests.PROPERTY + (walk.equals("wide-scalar") ? "=off" : "=on");
                    Process process = new ProcessBuilder(java, "--add-modules", "jdk.incubator.vector",
                            vector, "-cp", classPath, BenchMain.class.getName(), "wide", "one", scene, walk,
                            Integer.toString(rounds)).redirectError(ProcessBuilder.Redirect.DISCARD).start();
                    try (BufferedReader reader = new BufferedReader(
                            new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
                        for (String line; (line = reader.readLine()) != null; ) {
                            String[] f = line.split(" ");
                            results.computeIfAbsent(f[0], k -> new ArrayList<>()).add(Double.parseDouble(f[1]));
                        }
                    }
                    if (process.waitFor() != 0) {
                        err.println(scene + " " + walk + " failed");
                        return 1;
                    }
                }
            }
        }
        out.println("JDK " + Runtime.version() + ", ns of thread CPU time a ray, median of " + 2 * rounds + " rounds");
        results.forEach((key, values) -> {
            values.sort(null);
            out.printf("%-36s %6.0f%n", key, values.get(values.size() / 2));
        });
        return 0;
    }

    /** One process's rounds: prints "scene/walk/kind ns" a round. */
    private static void one(String scene, String walk, int rounds, PrintStream out) {
        Walks walks = WideBvhBenchmark.walks(scene);
        Traversal traversal = WideBvhBenchmark.walk(walks, walk);
        Ray[] rays = RandomRays.toward(walks.bounds(), 4);
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        long sink = 0;
        for (int round = -2; round < rounds; round++) {
            for (int kind = 0; kind < 2; kind++) {
                long start = threads.getCurrentThreadCpuTime();
                for (int rep = 0; rep < 8; rep++) {
                    for (Ray ray : rays) {
                        if (kind == 0) {
                            sink += Double.isNaN(walks.nearest(traversal, ray, Double.POSITIVE_INFINITY)) ? 0 : 1;
                        } else {
                            sink += walks.any(traversal, ray, 1.0) ? 1 : 0;
                        }
                    }
                }
                double ns = (threads.getCurrentThreadCpuTime() - start) / (8.0 * rays.length);
                if (round >= 0) {
                    out.println(scene + "/" + walk + "/" + (kind == 0 ? "closest" : "any-hit") + " " + ns);
                }
            }
        }
        if (sink == 42) {
            out.println("(sink)");
        }
    }
}

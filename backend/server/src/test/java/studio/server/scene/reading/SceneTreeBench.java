package studio.server.scene.reading;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;

import studio.server.preview.PreviewReadingBench;
import tools.jackson.databind.JsonNode;

/**
 * Not a test: times reading a scene file's JSON into a tree, {@link PlainTreeReader} against the
 * data-binding mapper's {@code readTree} (which must first be built). {@code cold plain|mapper FILE}:
 * the first read in a fresh JVM, as the command line does, wall time; run each a few times,
 * alternated. {@code warm [FILE]}: best and median of 40 reads of each, alternated, thread CPU time,
 * as the service reads a posted scene (without FILE: {@link PreviewReadingBench#scene}'s 10,000 spheres). Built as for {@code PreviewReadingBench}, then from backend/server:
 * <pre>
 *   java -cp target/classes:target/test-classes:$(cat /tmp/cp.txt) studio.server.scene.reading.SceneTreeBench cold plain ../../scenes/still-life.json
 * </pre>
 */
public final class SceneTreeBench {

    private SceneTreeBench() {
    }

    public static void main(String[] args) throws Exception {
        long start = System.nanoTime();
        byte[] json = args.length == (args[0].equals("cold") ? 3 : 2)
                ? Files.readAllBytes(Path.of(args[args.length - 1]))
                : PreviewReadingBench.scene(-1).getBytes(StandardCharsets.UTF_8);
        if (args[0].equals("cold")) {
            boolean plain = args[1].equals("plain");
            JsonNode tree = plain ? PlainTreeReader.read(json, false) : SceneReader.FullPath.MAPPER.readTree(json);
            System.out.printf(Locale.ROOT, "cold %s: %.1f ms (%d fields)%n", args[1], (System.nanoTime() - start) / 1e6, tree.size());
            return;
        }
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        long[] plain = new long[40], mapper = new long[40];
        for (int i = 0; i < plain.length; i++) {
            long t0 = cpu.getCurrentThreadCpuTime();
            JsonNode a = PlainTreeReader.read(json, true);
            long t1 = cpu.getCurrentThreadCpuTime();
            JsonNode b = SceneReader.FullPath.MAPPER.readTree(json);
            long t2 = cpu.getCurrentThreadCpuTime();
            if (!a.equals(b)) {
                throw new IllegalStateException("the trees differ");
            }
            plain[i] = t1 - t0;
            mapper[i] = t2 - t1;
        }
        Arrays.sort(plain);
        Arrays.sort(mapper);
        System.out.printf(Locale.ROOT, "warm, %,d bytes: PlainTreeReader best %.1f ms, median %.1f; mapper best %.1f ms, median %.1f%n",
                json.length, plain[0] / 1e6, plain[20] / 1e6, mapper[0] / 1e6, mapper[20] / 1e6);
    }
}

package studio.server.preview;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Locale;
import java.util.Random;

import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * Not a test: times how a live-view message is read at each drag step of a 10,000-sphere scene
 * (1.4 MB), both ways, alternated, thread CPU time: {@link PreviewRequest#parse} (one streaming
 * pass that keeps the scene's bytes and finds each object's range in them, {@link SceneObjectsInJson}),
 * then the objects compared with the last revision's byte for byte; against Jackson's tree doing
 * the same job (the message read as a tree, the scene written back to bytes, each object compared
 * with the last revision's tree). Run from backend:
 * <pre>
 *   mvn -B -q -pl server -am test-compile dependency:build-classpath -Dmdep.outputFile=/tmp/cp.txt -DskipFrontend -DskipFrontendTests
 *   cd server &amp;&amp; java -cp target/classes:target/test-classes:$(cat /tmp/cp.txt) studio.server.preview.PreviewReadingBench
 * </pre>
 */
public final class PreviewReadingBench {

    private static final JsonMapper TREES = JsonMapper.builder().build();
    private static final int ROUNDS = 40;

    private PreviewReadingBench() {
    }

    public static void main(String[] args) {
        byte[] before = message(1, -1), after = message(2, 4321); // one sphere moved
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        long[] streaming = new long[ROUNDS], tree = new long[ROUNDS];
        long changed = 0;
        PreviewRequest last = PreviewRequest.parse(before, 4096, 4096);
        JsonNode lastTree = TREES.readTree(before).get("scene");
        for (int i = 0; i < ROUNDS; i++) {
            long t0 = cpu.getCurrentThreadCpuTime();
            changed += changedByBytes(last, PreviewRequest.parse(after, 4096, 4096));
            long t1 = cpu.getCurrentThreadCpuTime();
            changed += changedByTree(lastTree, after);
            long t2 = cpu.getCurrentThreadCpuTime();
            streaming[i] = t1 - t0;
            tree[i] = t2 - t1;
        }
        System.out.printf(Locale.ROOT, "live-view message, %,d bytes, %d rounds (changed found: %d)%n", after.length, ROUNDS, changed);
        print("streaming (PreviewRequest, SceneObjectsInJson)", streaming);
        print("Jackson tree", tree);
    }

    private static int changedByBytes(PreviewRequest last, PreviewRequest next) {
        int[] a = last.objects(), b = next.objects();
        int changed = 0;
        for (int k = 0; k < b.length; k += SceneObjectsInJson.PER_OBJECT) {
            if (!Arrays.equals(last.scene(), a[k], a[k + 1], next.scene(), b[k], b[k + 1])) {
                changed++;
            }
        }
        return changed;
    }

    private static int changedByTree(JsonNode lastScene, byte[] message) {
        JsonNode root = TREES.readTree(message);
        if (!root.get("revision").isIntegralNumber() || root.get("width").intValue() < 1) {
            throw new IllegalStateException();
        }
        JsonNode scene = root.get("scene");
        byte[] bytes = TREES.writeValueAsBytes(scene); // kept, for a full read as POST /api/render reads it
        JsonNode objects = scene.get("objects"), lastObjects = lastScene.get("objects");
        int changed = bytes.length > 0 ? 0 : -1;
        for (int k = 0; k < objects.size(); k++) {
            if (!objects.get(k).equals(lastObjects.get(k))) {
                changed++;
            }
        }
        return changed;
    }

    private static void print(String what, long[] nanos) {
        long[] sorted = nanos.clone();
        Arrays.sort(sorted);
        System.out.printf(Locale.ROOT, "  %-48s best %.1f ms, median %.1f ms%n", what, sorted[0] / 1e6,
                sorted[sorted.length / 2] / 1e6);
    }

    /** A message with the 10,000 spheres of {@link #scene}. */
    static byte[] message(int revision, int moved) {
        return ("{\"revision\": " + revision + ", \"width\": 640, \"height\": 360, \"scene\": " + scene(moved) + "}")
                .getBytes(StandardCharsets.UTF_8);
    }

    /** A scene of 10,000 spheres in a grid, sphere {@code moved} (or none) shifted by 0.25 in x. */
    public static String scene(int moved) {
        Random random = new Random(20240611L);
        StringBuilder json = new StringBuilder(1 << 21);
        json.append("{\"version\": 1, ")
                .append("\"camera\": {\"position\": [0, 100, 110], \"lookAt\": [0, 0, 5], \"up\": [0, 1, 0], \"fov\": 40}, ")
                .append("\"lights\": [{\"type\": \"point\", \"position\": [30, 60, 40], \"color\": \"#ffffff\", \"intensity\": 0.8}],\n")
                .append("\"objects\": [\n");
        for (int i = 0; i < 10_000; i++) {
            double r = 0.25 + 0.2 * random.nextDouble();
            double x = -49.5 + i / 100 + 0.3 * (random.nextDouble() - 0.5) + (i == moved ? 0.25 : 0);
            double z = -49.5 + i % 100 + 0.3 * (random.nextDouble() - 0.5);
            json.append(String.format(Locale.ROOT, "  {\"type\": \"sphere\", \"center\": [%.6f, %.6f, %.6f], \"radius\": %.6f, "
                    + "\"material\": {\"type\": \"%s\", \"color\": \"#2e86c1\"}}%s%n", x, r, z, r,
                    random.nextBoolean() ? "chalk" : "plastic", i < 9_999 ? "," : ""));
        }
        return json.append("]}").toString();
    }
}

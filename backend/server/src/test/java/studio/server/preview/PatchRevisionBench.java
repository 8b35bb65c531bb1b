package studio.server.preview;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.function.Function;

import studio.engine.memory.MemoryGate;
import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.engine.render.RenderSettings;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;
import studio.server.scene.compiling.CompileRequest;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.reading.LazyValidation;
import studio.server.system.MemoryBudget;
import tools.jackson.databind.JsonNode;

/**
 * Not a test: the server's work on a patched revision of a live view of 10,000 spheres (as
 * {@code scripts/LiveViewBench.java}'s {@code spheres-10k}: one sphere moved a little each revision),
 * split into applying the patch, compiling the revision (reading the moved object and assembling the
 * engine's scene) and rendering its one-sample frame at 640x480 (two threads, wall time); thread CPU
 * time, median and best of the rounds, beside a build of the same engine scene from its objects.
 * With {@code --mesh}, {@code mesh-50k}'s kind of scene, its 50,000-triangle mesh moved. Run from backend:
 * <pre>
 *   mvn -B -q -pl server -am test-compile dependency:build-classpath -Dmdep.outputFile=/tmp/cp.txt -DskipFrontend -DskipFrontendTests
 *   cd server &amp;&amp; java -cp target/classes:target/test-classes:$(cat /tmp/cp.txt) studio.server.preview.PatchRevisionBench [--mesh]
 * </pre>
 */
public final class PatchRevisionBench {

    private static final int ROUNDS = 40, WIDTH = 640, HEIGHT = 480;

    private PatchRevisionBench() {
    }

    public static void main(String[] args) {
        boolean mesh = args.length > 0 && args[0].equals("--mesh");
        String moved = mesh ? "/objects/0/position" : "/objects/0/center";
        String at = mesh ? ", 1.4, 0.0]" : ", 0.8, 2.5]";
        LazyValidation validation = new LazyValidation();
        SceneCompiler compiler = SceneCompiler.standalone(validation);
        Function<byte[], CompiledScene> read = json -> compiler.compile(CompileRequest.of(json)
                .overriding(Map.of("image.width", WIDTH, "image.height", HEIGHT, "image.format", "png")).onThreads(1));
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        SceneReuse reuse = new SceneReuse(MemoryBudget.unlimited());
        PatchBase base = new PatchBase(MemoryBudget.unlimited(), 1 << 20);
        String first = "{\"revision\": 1, \"width\": " + WIDTH + ", \"height\": " + HEIGHT + ", \"scene\": " + (mesh ? meshScene() : scene()) + "}";
        PreviewRequest request = PreviewRequest.parse(first.getBytes(StandardCharsets.UTF_8), 4096, 4096);
        base.whole(1, request.scene());
        reuse.compile(request, MemoryGate.UNLIMITED, read);
        base.compiled();
        long[] patch = new long[ROUNDS], compile = new long[ROUNDS], whole = new long[ROUNDS], render = new long[ROUNDS];
        long[] reusing = new long[ROUNDS];
        Scene previous = null;
        long revision = 1;
        for (int i = 0; i < ROUNDS; i++) {
            String message = "{\"revision\": " + (revision + 1) + ", \"base\": " + revision + ", \"width\": " + WIDTH
                    + ", \"height\": " + HEIGHT + ", \"patch\": [{\"op\": \"replace\", \"path\": \"" + moved + "\", "
                    + "\"value\": [" + (0.01 * (i % 20)) + at + "}]}";
            long t0 = cpu.getCurrentThreadCpuTime();
            PreviewRequest next = PreviewRequest.parse(message.getBytes(StandardCharsets.UTF_8), 4096, 4096);
            revision++;
            JsonNode tree = base.patch(revision, next.base(), next.patch());
            long t1 = cpu.getCurrentThreadCpuTime();
            CompiledScene compiled = reuse.compilePatched(base.compiledTree(), tree, base.origins(), next,
                    MemoryGate.UNLIMITED, read).compiled();
            base.compiled();
            long t2 = cpu.getCurrentThreadCpuTime();
            Scene s = compiled.scene();
            List<SceneObject> objects = new ArrayList<>(s.objectCount());
            for (int k = 0; k < s.objectCount(); k++) {
                objects.add(new SceneObject(s.shape(k), s.material(k)));
            }
            long t3 = cpu.getCurrentThreadCpuTime();
            new Scene(s.camera(), objects, s.lights(), s.background(), s.ambient());
            long t4 = cpu.getCurrentThreadCpuTime();
            if (previous != null) {
                Scene.reusing(previous, s.camera(), objects, s.lights(), s.background(), s.ambient());
            }
            reusing[i] = cpu.getCurrentThreadCpuTime() - t4;
            previous = s;
            t4 = cpu.getCurrentThreadCpuTime();
            RenderSettings one = compiled.settings();
            RenderSettings oneSample = new RenderSettings(WIDTH, HEIGHT, studio.engine.sampler.Sampler.of("jittered", 1),
                    one.maxDepth(), 2, one.seed(), one.minPathWeight(), 0);
            long w0 = System.nanoTime();
            Renderer.render(RenderRequest.of(s, oneSample));
            long t5 = t4 + System.nanoTime() - w0;
            patch[i] = t1 - t0;
            compile[i] = t2 - t1;
            whole[i] = t4 - t3;
            render[i] = t5 - t4;
        }
        System.out.printf(Locale.ROOT, "patched revisions of %s, %d rounds, thread CPU ms (median, best)%n",
                mesh ? "a 50,000-triangle mesh moved" : "10,001 objects, one sphere moved", ROUNDS);
        print("parse + apply the patch", patch);
        print("compile (read the object, assemble the scene)", compile);
        print("engine scene built in full (for comparison)", whole);
        print("engine scene reusing the last one's (Scene.reusing)", reusing);
        print("one-sample frame 640x480, 2 threads, wall time", render);
        reuse.close();
        base.close();
        validation.close();
    }

    private static void print(String what, long[] nanos) {
        long[] sorted = nanos.clone();
        Arrays.sort(sorted);
        System.out.printf(Locale.ROOT, "  %-48s %7.2f %7.2f%n", what, sorted[sorted.length / 2] / 1e6, sorted[0] / 1e6);
    }

    /** mesh-50k's kind of scene: a torus of 50,000 triangles (inline OBJ, moved), a mirror ball, a floor, two lights. */
    static String meshScene() {
        StringBuilder obj = new StringBuilder();
        int major = 250, minor = 100;
        for (int i = 0; i < major; i++) {
            double u = 2 * Math.PI * i / major;
            for (int j = 0; j < minor; j++) {
                double v = 2 * Math.PI * j / minor, nx = Math.cos(v) * Math.cos(u), ny = Math.cos(v) * Math.sin(u);
                obj.append(String.format(Locale.ROOT, "v %.5f %.5f %.5f\\nvn %.5f %.5f %.5f\\n", Math.cos(u) + 0.35 * nx,
                        Math.sin(u) + 0.35 * ny, 0.35 * Math.sin(v), nx, ny, Math.sin(v)));
            }
        }
        for (int i = 0; i < major; i++) {
            for (int j = 0; j < minor; j++) {
                int a = i * minor + j + 1, b = ((i + 1) % major) * minor + j + 1;
                int c = ((i + 1) % major) * minor + (j + 1) % minor + 1, d = i * minor + (j + 1) % minor + 1;
                obj.append(String.format("f %d//%d %d//%d %d//%d\\nf %d//%d %d//%d %d//%d\\n", a, a, b, b, c, c, a, a, c, c, d, d));
            }
        }
        return "{\"camera\": {\"position\": [0, 2.5, 6.5], \"lookAt\": [0, 1.2, 0], \"fov\": 45},"
                + "\"render\": {\"sampler\": \"sobol\", \"samples\": 16, \"maxDepth\": 4},"
                + "\"lights\": [{\"type\": \"point\", \"position\": [4, 7, 5], \"intensity\": 0.9},"
                + "{\"type\": \"point\", \"position\": [-5, 4, 3], \"color\": \"#a8c0ff\", \"intensity\": 0.4}],"
                + "\"objects\": [{\"type\": \"mesh\", \"obj\": \"" + obj + "\", \"position\": [0, 1.4, 0], \"rotation\": [0, 25, 0],"
                + "\"material\": {\"type\": \"plastic\", \"color\": \"#e0a030\"}},"
                + "{\"type\": \"sphere\", \"center\": [2, 0.5, 1], \"radius\": 0.5, \"material\": {\"type\": \"mirror\"}},"
                + "{\"type\": \"plane\", \"material\": {\"type\": \"chalk\", \"color\": \"#d8d8d8\"}}]}";
    }

    /** spheres-10k's kind of scene: a mirror ball in front (moved), 9,999 small spheres, a floor, two lights. */
    static String scene() {
        Random random = new Random(1);
        String[] materials = {"chalk", "plastic", "metal"};
        StringBuilder json = new StringBuilder(1 << 21);
        json.append("{\"camera\": {\"position\": [0, 3, 9], \"lookAt\": [0, 1, 0], \"fov\": 45},")
                .append("\"render\": {\"sampler\": \"sobol\", \"samples\": 16, \"maxDepth\": 4},")
                .append("\"lights\": [{\"type\": \"point\", \"position\": [4, 7, 5], \"intensity\": 0.9},")
                .append("{\"type\": \"point\", \"position\": [-5, 4, 3], \"color\": \"#a8c0ff\", \"intensity\": 0.4}],")
                .append("\"objects\": [{\"type\": \"sphere\", \"center\": [0, 0.8, 2.5], \"radius\": 0.6, \"material\": {\"type\": \"mirror\"}}");
        for (int i = 1; i < 10_000; i++) {
            json.append(String.format(Locale.ROOT, ",{\"type\": \"sphere\", \"center\": [%.3f, %.3f, %.3f], \"radius\": 0.07, "
                            + "\"material\": {\"type\": \"%s\", \"color\": \"#%06x\"}}", -4 + 8 * random.nextDouble(),
                    0.07 + 3 * random.nextDouble(), -4 + 6 * random.nextDouble(), materials[i % 3], random.nextInt(1 << 24)));
        }
        return json.append(",{\"type\": \"plane\", \"material\": {\"type\": \"chalk\", \"color\": \"#b0b0b0\"}}]}").toString();
    }
}

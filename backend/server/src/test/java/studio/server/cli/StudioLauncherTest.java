package studio.server.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.IntStream;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import studio.server.scene.compiling.CompileRequest;
import studio.engine.geometry.TriangleMesh;
import studio.engine.material.MaterialKind;
import studio.engine.scene.Scene;
import studio.engine.scene.ShapeSet;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.compiling.MeshFiles;
import studio.server.scene.compiling.SceneCompiler;
import studio.server.scene.reading.LazyValidation;

/**
 * {@code bin/studio}, the launcher, run with a stand-in JDK 25 whose {@code java} writes down its
 * arguments: the JVM options it picks for each kind of command.
 */
class StudioLauncherTest {

    private static final Path LAUNCHER = Path.of("../../bin/studio").toAbsolutePath().normalize();
    private static final String QUICK_COMPILER = "-XX:TieredStopAtLevel=1";

    @TempDir
    Path dir;
    private Path calls;
    /** The jar the launcher is given (STUDIO_JAR), in the test's directory. */
    private String jarName = "studio.jar";

    private static final String VECTOR_MODULES = "java.base jdk.incubator.vector jdk.jfr";

    @BeforeEach
    void standInJdk() throws IOException {
        standInJdk("25.0.1", VECTOR_MODULES);
    }

    private void standInJdk(String version) throws IOException {
        standInJdk(version, VECTOR_MODULES);
    }

    /** A stand-in JDK whose release file gives this version and these modules (MODULES, as a JDK's). */
    private void standInJdk(String version, String modules) throws IOException {
        Path bin = Files.createDirectories(dir.resolve("jdk/bin"));
        Files.writeString(dir.resolve("jdk/release"), "IMPLEMENTOR=\"Stand-in\"\nJAVA_VERSION=\"" + version
                + "\"\nMODULES=\"" + modules + "\"\n");
        calls = dir.resolve("calls");
        Files.deleteIfExists(calls); // a new JDK: only its calls count
        Path java = bin.resolve("java");
        // writes down its arguments; as `-Djarmode=tools -jar J extract --destination D` it makes D
        Files.writeString(java, """
                #!/usr/bin/env bash
                echo "$*" >> '%s'
                for ((i = 1; i < $#; i++)); do
                  if [[ "${!i}" == --destination ]]; then next=$((i + 1)); mkdir -p "${!next}"; fi
                done
                """.formatted(calls));
        Files.setPosixFilePermissions(java, PosixFilePermissions.fromString("rwxr-xr-x"));
        Files.writeString(dir.resolve("studio.jar"), "a jar");
    }

    /** The options of the JVM the launcher ends with (its last call: the render or the service). */
    private String launched(String... args) throws Exception {
        List<String> lines = calls(args);
        String last = lines.get(lines.size() - 1);
        return last.substring(0, last.indexOf(" -jar "));
    }

    /** Every call the launcher made of the stand-in java, in order. */
    private List<String> calls(String... args) throws Exception {
        List<String> command = new ArrayList<>(List.of("bash", LAUNCHER.toString()));
        command.addAll(List.of(args));
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true);
        builder.environment().put("JAVA", dir.resolve("jdk/bin/java").toString());
        builder.environment().put("STUDIO_JAR", dir.resolve(jarName).toString());
        Process process = builder.start();
        String output = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(process.waitFor(30, TimeUnit.SECONDS)).as("the launcher finished").isTrue();
        assertThat(process.exitValue()).as(output).isZero();
        return Files.readAllLines(calls);
    }

    /** The jar a call runs: the word after {@code -jar}. */
    private static String jarOf(String call) {
        String after = call.substring(call.indexOf(" -jar ") + " -jar ".length());
        return after.substring(0, after.indexOf(' '));
    }

    @Test
    void onJdk17TheArchiveIsRecordedWithTheJarItIsUsedWith() throws Exception {
        standInJdk("17.0.15");
        List<String> calls = calls("render", "s.json", "--width", "800", "--height", "600", "--samples", "1");

        String training = calls.stream().filter(c -> c.contains("-XX:ArchiveClassesAtExit=")).findFirst().orElseThrow();
        String render = calls.get(calls.size() - 1);
        assertThat(render).contains("-XX:SharedArchiveFile=", "-XX:+UseParallelGC", QUICK_COMPILER);
        // JDK 17 refuses an archive recorded with the jar at any other path
        assertThat(jarOf(training)).isEqualTo(jarOf(render)).endsWith("studio-cds/studio.jar");
        assertThat(dir.resolve("studio-cds/stamp")).exists();
        assertThat(calls("render", "s.json")).as("recorded once").hasSize(calls.size() + 1);
    }

    /** The jar's tools mode unpacks it under its own file name, which the training run and the render run. */
    @Test
    void aJarOfAnotherNameRunsUnpackedUnderItsOwnName() throws Exception {
        jarName = "build-7.jar";
        Files.writeString(dir.resolve(jarName), "a jar");
        List<String> calls = calls("render", "s.json");

        String training = calls.stream().filter(c -> c.contains("-XX:AOTCacheOutput=")).findFirst().orElseThrow();
        assertThat(jarOf(training)).contains("build-7-cds.tmp.").endsWith("/build-7.jar");
        assertThat(jarOf(calls.get(calls.size() - 1))).endsWith("build-7-cds/build-7.jar");
    }

    /**
     * Two jars in one directory (two builds side by side) keep a cache each: with one cache a
     * directory, each run of the other jar found the cache recorded for the first and trained again
     * (seen as 2.5 s more on every render when two builds were alternated).
     */
    @Test
    void twoJarsInOneDirectoryKeepACacheEach() throws Exception {
        Files.writeString(dir.resolve("build-7.jar"), "another jar");
        Files.setLastModifiedTime(dir.resolve("studio.jar"), FileTime.fromMillis(1_700_000_000_000L));
        Files.setLastModifiedTime(dir.resolve("build-7.jar"), FileTime.fromMillis(1_700_000_100_000L));
        calls("render", "s.json");
        jarName = "build-7.jar";
        calls("render", "s.json");
        jarName = "studio.jar";
        List<String> calls = calls("render", "s.json");

        assertThat(calls.stream().filter(c -> c.contains("-XX:AOTCacheOutput="))).as("training runs").hasSize(2);
        assertThat(jarOf(calls.get(calls.size() - 1))).endsWith("studio-cds/studio.jar");
    }

    @Test
    void onJdk25TheCacheIsRecordedApartAndMovedIntoPlace() throws Exception {
        List<String> calls = calls("render", "s.json");

        String training = calls.stream().filter(c -> c.contains("-XX:AOTCacheOutput=")).findFirst().orElseThrow();
        assertThat(training).contains("studio-cds.tmp.");
        assertThat(jarOf(calls.get(calls.size() - 1))).endsWith("studio-cds/studio.jar");
        assertThat(dir.resolve("studio-cds/stamp")).exists();
        assertThat(dir.resolve("studio-cds/java")).content().contains(" aot");
    }

    /**
     * The training run renders bin/training/'s scenes in one JVM ({@code studio.jar train}), each a
     * valid scene at 16 samples, one of each kind the engine treats apart, so the cache's profiles
     * cover every kind's paths: a crowd of 64 objects or more (light buffers) with glass and a mesh
     * among them, a still life that searches its tree, glass among fewer objects than buffers
     * need, and a mesh searched one object after the other.
     */
    @Test
    void theTrainingRunRendersOneSceneOfEachKind() throws Exception {
        List<String> calls = calls("render", "s.json");
        String training = calls.stream().filter(c -> c.contains("-XX:AOTCacheOutput=")).findFirst().orElseThrow();
        Path scenes = LAUNCHER.getParent().resolve("training");
        List<String> names = List.of("crowd", "still-life", "glass", "knot");
        StringBuilder files = new StringBuilder(" train");
        for (String name : names) {
            files.append(' ').append(scenes.resolve(name + ".json"));
        }
        assertThat(training).endsWith(files.toString());

        Scene crowd = compile(scenes.resolve("crowd.json"));
        assertThat(bounded(crowd)).isGreaterThanOrEqualTo(ShapeSet.LIGHT_BUFFER_MIN);
        assertThat(has(crowd, MaterialKind.GLASS)).as("glass in the crowd").isTrue();
        assertThat(hasMesh(crowd)).as("a mesh in the crowd").isTrue();

        Scene stillLife = compile(scenes.resolve("still-life.json"));
        assertThat(stillLife.objectCount()).as("searched through its tree").isGreaterThan(ShapeSet.LINEAR_MAX);

        Scene glass = compile(scenes.resolve("glass.json"));
        assertThat(has(glass, MaterialKind.GLASS)).as("glass").isTrue();
        assertThat(glass.objectCount()).isGreaterThan(ShapeSet.LINEAR_MAX);
        assertThat(bounded(glass)).isLessThan(ShapeSet.LIGHT_BUFFER_MIN);

        Scene knot = compile(scenes.resolve("knot.json"));
        assertThat(knot.objectCount()).as("searched one object after the other").isLessThanOrEqualTo(ShapeSet.LINEAR_MAX);
        assertThat(hasMesh(knot)).isTrue();
    }

    /** How many of the scene's objects have bounds (all but planes). */
    private static long bounded(Scene scene) {
        return IntStream.range(0, scene.objectCount()).filter(i -> scene.shape(i).bounds().isBounded()).count();
    }

    private static Scene compile(Path scene) throws IOException {
        try (LazyValidation validation = new LazyValidation()) {
            CompiledScene compiled = SceneCompiler.standalone(validation, MeshFiles.in(scene.getParent()))
                    .compile(CompileRequest.of(Files.readAllBytes(scene)));
            assertThat(compiled.settings().sampler().samplesPerPixel()).as(scene + "'s samples").isEqualTo(16);
            assertThat(compiled.settings().width() * compiled.settings().height()).as(scene + "'s size")
                    .isEqualTo(160 * 120);
            // the last scene's profiles count most: a kind of surface the training's scenes leave out
            // is a path a render's JIT compiles as never taken (the still life deoptimized at its
            // first mirror, glass at its first glass, with the knot's scene in plastic alone)
            Scene built = compiled.scene();
            assertThat(has(built, MaterialKind.CHALK)).as(scene + " has chalk").isTrue();
            assertThat(has(built, MaterialKind.GLASS)).as(scene + " has glass").isTrue();
            assertThat(has(built, MaterialKind.MIRROR) || has(built, MaterialKind.METAL))
                    .as(scene + " has a mirror or metal").isTrue();
            return built;
        }
    }

    private static boolean has(Scene scene, MaterialKind kind) {
        for (int i = 0; i < scene.objectCount(); i++) {
            if (scene.material(i).kind() == kind) {
                return true;
            }
        }
        return false;
    }

    private static boolean hasMesh(Scene scene) {
        for (int i = 0; i < scene.objectCount(); i++) {
            if (scene.shape(i) instanceof TriangleMesh) {
                return true;
            }
        }
        return false;
    }

    @Test
    void aRenderOfAtMostAMillionSamplesTakesTheQuickCompilerAlone() throws Exception {
        assertThat(launched("render", "s.json", "--width", "800", "--height", "600", "--samples", "1"))
                .contains("-XX:+UseParallelGC", QUICK_COMPILER, "-XX:AOTCache=");
        assertThat(launched("render", "s.json", "--samples", "2", "-o", "x.png", "--height", "600", "--width", "800"))
                .contains(QUICK_COMPILER);
        assertThat(launched("render", "s.json", "--width", "1000", "--height", "1000", "--samples", "1"))
                .contains(QUICK_COMPILER);
    }

    @Test
    void aQuickRenderInlinesTheBvhBoxTestIntoItsTraversalAndNothingElseDoes() throws Exception {
        String quick = launched("render", "s.json", "--width", "800", "--height", "600", "--samples", "1");
        List<String> inlined = new ArrayList<>();
        for (String option : quick.split(" ")) {
            if (option.startsWith("-XX:CompileCommand=inline,")) {
                inlined.add(option.substring("-XX:CompileCommand=inline,".length()));
            }
        }
        assertThat(quick).contains("-XX:CompileCommand=quiet");
        assertThat(inlined).containsExactlyInAnyOrder("java/lang/Math.max", "java/lang/Math.min",
                "studio/engine/accel/Slab.entryWithoutNaN", "studio/engine/accel/Slab.hitsWithoutNaN",
                "studio/engine/accel/Slab.overlap");
        // a command naming a method that is not there would be silently ignored
        for (String method : inlined) {
            Class<?> type = Class.forName(method.substring(0, method.lastIndexOf('.')).replace('/', '.'));
            String name = method.substring(method.lastIndexOf('.') + 1);
            assertThat(type.getDeclaredMethods()).as(method).anyMatch(m -> m.getName().equals(name));
        }
        assertThat(launched("render", "s.json", "--width", "800", "--height", "600", "--samples", "16"))
                .doesNotContain("CompileCommand");
        assertThat(launched()).doesNotContain("CompileCommand");
    }

    @Test
    void aLongerRenderOrOneWhoseSizeTheSceneGivesKeepsBothCompilers() throws Exception {
        assertThat(launched("render", "s.json", "--width", "800", "--height", "600", "--samples", "16"))
                .contains("-XX:+UseParallelGC").doesNotContain(QUICK_COMPILER);
        assertThat(launched("render", "s.json", "--width", "1001", "--height", "1000", "--samples", "1"))
                .doesNotContain(QUICK_COMPILER);
        assertThat(launched("render", "s.json", "--samples", "1")).doesNotContain(QUICK_COMPILER);
        assertThat(launched("render", "s.json", "--width", "800", "--height", "600")).doesNotContain(QUICK_COMPILER);
        assertThat(launched("render", "s.json", "--width", "8", "--height", "6", "--samples", "x"))
                .doesNotContain(QUICK_COMPILER);
        assertThat(launched("render", "s.json", "--width", "8", "--height", "6", "--samples", "999999999999"))
                .doesNotContain(QUICK_COMPILER);
        assertThat(launched("render", "s.json", "--width", "8", "--height", "6", "--samples"))
                .doesNotContain(QUICK_COMPILER);
    }

    /**
     * The launcher never reads the scene: the same command line gets the same options whatever
     * the file holds (a mesh, a glTF model, spheres) or whether it exists at all.
     */
    @Test
    void theOptionsDependOnTheCommandLineAloneNotOnTheScenesText() throws Exception {
        Path spheres = Files.writeString(dir.resolve("spheres.json"),
                "{\"objects\": [{\"type\": \"sphere\", \"radius\": 1}]}");
        Path mesh = Files.writeString(dir.resolve("mesh.json"),
                "{\"objects\": [{\"type\" :\n \"mesh\", \"file\": \"knot.obj\"}]}");
        Path model = Files.writeString(dir.resolve("model.json"),
                "{\"objects\": [{\"type\": \"gltf\", \"file\": \"model.glb\"}]}");
        Path missing = dir.resolve("missing.json");
        for (String[] size : new String[][] {{"--samples", "16"}, {"--width", "800", "--height", "600", "--samples", "1"},
                {"--threads", "2"}}) {
            List<String> options = new ArrayList<>();
            for (Path scene : new Path[] {spheres, mesh, model, missing}) {
                List<String> args = new ArrayList<>(List.of("render", scene.toString(), "-o", "x.png"));
                args.addAll(List.of(size));
                options.add(launched(args.toArray(String[]::new)));
            }
            assertThat(options).as(String.join(" ", size)).containsOnly(options.get(0));
        }
    }

    /** Every longer render runs without on-stack replacement; a short one, on C1 alone, and the service keep it. */
    @Test
    void aLongerRenderRunsWithoutOnStackReplacement() throws Exception {
        String noOsr = "-XX:-UseOnStackReplacement";
        assertThat(launched("render", "s.json", "-o", "x.png", "--samples", "16")).contains(noOsr);
        assertThat(launched("render", "--threads", "2", "-o", "x.png", "s.json")).contains(noOsr);
        assertThat(launched("render", "s.json", "--width", "800", "--height", "600", "--samples", "1"))
                .doesNotContain(noOsr);
        assertThat(launched()).doesNotContain(noOsr);
    }

    /**
     * A render both compilers run gives C2 two threads on a machine of two or three online cores
     * (the JVM's own count there gives it one), and no other run changes the count.
     */
    @Test
    void aLongerRenderOnTwoOrThreeCoresGivesC2TwoThreads() throws Exception {
        String twoC2Threads = "-XX:CICompilerCount=3";
        Path online = Path.of("/sys/devices/system/cpu/online");
        boolean fewCores = Files.isReadable(online) && Files.readString(online).trim().matches("0-[12]");
        String longer = launched("render", "s.json", "--width", "800", "--height", "600", "--samples", "16");
        if (fewCores) {
            assertThat(longer).contains(twoC2Threads);
        } else {
            assertThat(longer).doesNotContain(twoC2Threads);
        }
        assertThat(launched("render", "s.json", "--width", "800", "--height", "600", "--samples", "1"))
                .doesNotContain(twoC2Threads);
        assertThat(launched()).doesNotContain(twoC2Threads);
    }

    @Test
    void theServiceKeepsTheJvmsDefaults() throws Exception {
        assertThat(launched()).doesNotContain("-XX:+UseParallelGC", QUICK_COMPILER).contains("-XX:AOTCache=");
        assertThat(launched("--server.port=8081", "--samples", "1")).doesNotContain(QUICK_COMPILER);
    }

    /**
     * A JDK of version 20 or newer with the Vector API's incubator module runs the service with it,
     * the training run too, into a cache of its own (the cache keeps the module graph it was
     * recorded with); renders, quick or longer, run without it from the plain cache; JDK 17, and a
     * runtime built without the module, run without it.
     */
    @Test
    void aJdkWithTheVectorModuleRunsTheServiceWithItAndRendersWithout() throws Exception {
        String module = "--add-modules jdk.incubator.vector";
        List<String> calls = calls();
        String training = calls.stream().filter(c -> c.contains(" train ")).findFirst().orElseThrow();
        assertThat(training).contains(module).contains("studio-cds-vector.tmp.");
        assertThat(calls.get(calls.size() - 1)).contains(module).contains("studio-cds-vector/studio.jar");
        assertThat(dir.resolve("studio-cds-vector/java")).content().contains(" aot vector");

        for (String samples : List.of("1", "16")) {
            int before = calls().size();
            calls = calls("render", "s.json", "--width", "800", "--height", "600", "--samples", samples);
            assertThat(calls.subList(before, calls.size())).as("a render and any training run")
                    .isNotEmpty().noneMatch(c -> c.contains("add-modules"));
            assertThat(jarOf(calls.get(calls.size() - 1))).endsWith("studio-cds/studio.jar");
        }
        assertThat(dir.resolve("studio-cds/java")).content().doesNotContain("vector");

        standInJdk("17.0.15");
        assertThat(calls()).noneMatch(c -> c.contains("add-modules"));

        standInJdk("25.0.1", "java.base jdk.jfr");
        assertThat(calls()).noneMatch(c -> c.contains("add-modules"));
    }
}

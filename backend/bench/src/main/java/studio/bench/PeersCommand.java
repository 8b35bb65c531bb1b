package studio.bench;

import java.io.IOException;
import java.io.PrintStream;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import javax.imageio.ImageIO;

import jakarta.validation.Validation;
import jakarta.validation.ValidatorFactory;

import studio.server.cli.Args;
import studio.server.scene.format.InvalidSceneException;
import studio.server.scene.reading.SceneReader;

/**
 * {@code studio-bench.jar peers [--runs 5] [--scenes still-life,spheres-10k,mesh-100k,glass] [--samples 1,16]
 * [--out docs/bench] [--work DIR] [--threads 2] [--studio-jar ...] [--povray ...] [--sunflow-jar ...]}:
 * ours, POV-Ray 3.7 and Sunflow on the same scenes, side by side. A scene is one of the benchmark's
 * names or any scene file ({@code .json}, its meshes beside it), named by its file name: how a
 * scene the benchmark was not tuned on is checked. For each scene it first renders a
 * silhouette mask with each (1 sample per pixel through the pixel centre) and compares ours with
 * each peer's; then, for each number of samples per pixel, it times whole processes, the three
 * renderers alternated in a rotating order, {@code --runs} rounds, and reports medians and the
 * ratios ours/peer. Writes {@code peers.csv} and {@code peers.md} to {@code --out}.
 */
public final class PeersCommand {

    static final int OK = 0, IO_ERROR = 1, INVALID = 2, MASKS_DISAGREE = 3;
    /** The samples per pixel the targets are stated at. */
    static final int TARGET_SAMPLES = 16;
    static final int WIDTH = 800, HEIGHT = 600;
    static final Map<String, String> SCENE_FILES = scenes();

    static final String USAGE = "usage: java -jar studio-bench.jar peers [--runs 5] [--scenes "
            + String.join(",", SCENE_FILES.keySet()) + "|FILE.json,...] [--samples 1,16] [--out docs/bench] [--work DIR] "
            + "[--threads 2] [--scenes-dir scenes] [--studio-jar backend/server/target/studio.jar] [--launcher bin/studio|none] "
            + "[--povray /usr/bin/povray] [--sunflow-jar /usr/share/java/sunflow.jar] [--java PATH]";

    private PeersCommand() {
    }

    /** Benchmark scene name to scene file (in --scenes-dir); null: generated ({@link #generated}). */
    private static Map<String, String> scenes() {
        Map<String, String> m = new LinkedHashMap<>();
        m.put("still-life", "still-life.json");
        m.put("spheres-10k", null);
        m.put("mesh-100k", null);
        m.put("glass", "glass-pattern.json");
        return m;
    }

    /**
     * A generated scene's file: {@code spheres-10k} ({@link SpheresScene}) or {@code mesh-100k}
     * ({@link MeshScene}, whose OBJ file it writes into {@code dir}, beside where the scene file goes).
     */
    public static byte[] generated(String name, Path dir) throws IOException {
        String json = switch (name) {
            case "spheres-10k" -> SpheresScene.json(100);
            case "mesh-100k" -> {
                Files.createDirectories(dir);
                MeshScene.writeObj(MeshScene.mesh(), dir.resolve(MeshScene.OBJ_FILE));
                yield MeshScene.json(MeshScene.OBJ_FILE);
            }
            default -> throw new IllegalArgumentException("no generated scene '" + name + "'");
        };
        return json.getBytes(StandardCharsets.UTF_8);
    }

    public static int run(String[] args, PrintStream out, PrintStream err) {
        Options o = Args.options(args, Options::parse, USAGE, err);
        if (o == null) {
            return INVALID;
        }
        if (o.help) {
            out.println(USAGE);
            return OK;
        }
        System.setProperty("java.awt.headless", "true");
        Renderers renderers;
        try {
            renderers = new Renderers(o.java, o.studioJar, o.povray, o.sunflowJar, benchClasses(), WIDTH, HEIGHT,
                    o.threads, o.launcher);
        } catch (URISyntaxException e) {
            err.println("error: cannot find this module's classes: " + e.getMessage());
            return IO_ERROR;
        }
        if (o.launcher == null) {
            // bin/studio is looked for in the working directory: run from elsewhere, ours went without it, slower, unsaid
            err.println("note: ours runs " + MachineSetup.ours(renderers)
                    + " (bin/studio is looked for in the working directory; --launcher PATH names it)");
        }
        for (Path tool : List.of(o.java, o.studioJar, o.povray, o.sunflowJar)) {
            if (!Files.isRegularFile(tool)) {
                err.println("error: not found: " + tool + (tool.equals(o.studioJar)
                        ? " (build it: mvn -B -o -f backend/pom.xml -Pbench package -DskipTests -DskipFrontend)" : ""));
                return IO_ERROR;
            }
        }

        List<PeerResult> rows = new ArrayList<>();
        try (ValidatorFactory validation = Validation.buildDefaultValidatorFactory()) {
            SceneReader reader = new SceneReader(validation.getValidator());
            Files.createDirectories(o.work);
            int turn = 0;
            for (String scene : o.scenes) {
                String name = sceneName(scene);
                String named = SCENE_FILES.get(scene); // null for a scene file, or a generated scene
                Path file = isSceneFile(scene) ? Path.of(scene) : named == null ? null : o.scenesDir.resolve(named);
                Path dir = o.work.resolve(name);
                byte[] json = file == null ? generated(name, dir) : Files.readAllBytes(file);
                Path meshFolder = file == null ? dir : file.toAbsolutePath().getParent();
                PeerScene peerScene;
                try {
                    peerScene = PeerScene.write(name, json, reader, dir, renderers, o.samples, meshFolder);
                } catch (InvalidSceneException | IllegalArgumentException e) {
                    err.println("error: invalid scene " + name + ": " + e.getMessage());
                    return INVALID;
                }
                MaskCheck masks = maskCheck(peerScene, renderers, err);
                for (int samples : o.samples) {
                    PeerResult row = PeerResult.empty(name, samples, masks);
                    for (int round = 0; round < o.runs; round++, turn++) {
                        for (int k = 0; k < 3; k++) {
                            Renderers.Peer peer = Renderers.Peer.values()[(turn + k) % 3];
                            long nanos = timed(peerScene, renderers, peer, samples);
                            row.nanos().get(peer).add(nanos);
                            err.printf(Locale.ROOT, "  %s %d spp, run %d: %-8s %8.0f ms%n", name, samples, round + 1,
                                    peer.label, nanos / 1e6);
                        }
                    }
                    row = row.withDiff(Masks.meanAbsoluteDifference(
                            ImageIO.read(output(peerScene, Renderers.Peer.OURS, samples).toFile()),
                            ImageIO.read(output(peerScene, Renderers.Peer.POVRAY, samples).toFile())));
                    rows.add(row);
                    err.print(PeersReport.table(List.of(row)));
                }
            }
        } catch (IOException e) {
            err.println("error: " + e.getMessage());
            return IO_ERROR;
        }

        String setup = MachineSetup.describe(o.java, o.povray, o.sunflowJar, renderers, o.runs);
        try {
            Files.createDirectories(o.out);
            Files.writeString(o.out.resolve("peers.csv"), PeersReport.csv(rows));
            Files.writeString(o.out.resolve("peers.md"), PeersReport.markdown(rows, setup, TARGET_SAMPLES));
        } catch (IOException e) {
            err.println("error: cannot write to " + o.out + ": " + e.getMessage());
            return IO_ERROR;
        }
        out.println(setup);
        out.println();
        out.print(PeersReport.table(rows));
        out.println(PeersReport.targetLine(rows, TARGET_SAMPLES));
        out.println("wrote " + o.out.resolve("peers.csv") + " and " + o.out.resolve("peers.md") + "; images in " + o.work);
        return rows.stream().allMatch(PeerResult::masksAgree) ? OK : MASKS_DISAGREE;
    }

    /**
     * Renders the scene's mask with each renderer at one sample per pixel and compares ours with
     * POV-Ray's and Sunflow's. These renders also warm the file cache for the timed runs.
     */
    static MaskCheck maskCheck(PeerScene s, Renderers r, PrintStream err) throws IOException {
        Path ours = s.dir().resolve("mask-ours.png"), pov = s.dir().resolve("mask-povray.png"),
                sun = s.dir().resolve("mask-sunflow.png");
        ProcessRun.time(r.ours(s.ourMaskJson(), ours, 1), ours, s.dir().resolve("mask-ours.log"));
        ProcessRun.time(r.povray(s.povMask(), pov, 1), pov, s.dir().resolve("mask-povray.log"));
        ProcessRun.time(r.sunflow(s.sunflowMask(), sun), sun, s.dir().resolve("mask-sunflow.log"));
        MaskCheck check = MaskCheck.of(Masks.mask(ImageIO.read(ours.toFile())), Masks.mask(ImageIO.read(pov.toFile())),
                Masks.mask(ImageIO.read(sun.toFile())));
        err.printf(Locale.ROOT, "%s: masks (objects on %.1f%% of ours) agree with POV-Ray on %.3f%% of the pixels "
                        + "(IoU %.3f%%), with Sunflow on %.3f%% (IoU %.3f%%)%n", s.name(), 100 * check.coverage(),
                100 * check.agreementPovray(), 100 * check.iouPovray(), 100 * check.agreementSunflow(),
                100 * check.iouSunflow());
        return check;
    }

    static long timed(PeerScene s, Renderers r, Renderers.Peer peer, int samples) throws IOException {
        Path out = output(s, peer, samples);
        Path log = s.dir().resolve(peer.label + "-" + samples + ".log");
        List<String> command = switch (peer) {
            case OURS -> r.ours(s.ourJson(), out, samples);
            case POVRAY -> r.povray(s.pov(), out, samples);
            case SUNFLOW -> r.sunflow(s.sunflow().get(samples), out);
        };
        return ProcessRun.time(command, out, log);
    }

    static Path output(PeerScene s, Renderers.Peer peer, int samples) {
        return s.dir().resolve(peer.label + "-" + samples + ".png");
    }

    /** Whether a --scenes entry is a scene file rather than one of the benchmark's names. */
    static boolean isSceneFile(String scene) {
        return scene.endsWith(".json");
    }

    /** A --scenes entry's name in the report and the work folder: a file's name without ".json". */
    static String sceneName(String scene) {
        if (!isSceneFile(scene)) {
            return scene;
        }
        String file = Path.of(scene).getFileName().toString();
        return file.substring(0, file.length() - ".json".length());
    }

    /** Where this module's classes are: its jar, or target/classes when run from the build. */
    static Path benchClasses() throws URISyntaxException {
        return Path.of(SunflowRender.class.getProtectionDomain().getCodeSource().getLocation().toURI());
    }

    /** The parsed command line. */
    static final class Options {
        int runs = 5;
        int threads = 2;
        List<String> scenes = List.copyOf(SCENE_FILES.keySet());
        List<Integer> samples = List.of(1, TARGET_SAMPLES);
        Path out = Path.of("docs/bench");
        Path work = Path.of(System.getProperty("java.io.tmpdir"), "studio-peers");
        Path scenesDir = Path.of("scenes");
        Path studioJar = Path.of("backend/server/target/studio.jar");
        /** Runs ours through bin/studio (with its class-data-sharing archive) when that exists; --launcher none: java -jar. */
        Path launcher = Files.isExecutable(Path.of("bin/studio")) ? Path.of("bin/studio") : null;
        Path povray = Path.of("/usr/bin/povray");
        Path sunflowJar = Path.of("/usr/share/java/sunflow.jar");
        Path java = ProcessHandle.current().info().command().map(Path::of).orElse(Path.of("java"));
        boolean help;

        static Options parse(String[] args) {
            Options o = new Options();
            for (int i = 0; i < args.length; i++) {
                String a = args[i];
                switch (a) {
                    case "-h", "--help" -> o.help = true;
                    case "--runs" -> o.runs = Args.positive(args, ++i, a);
                    case "--threads" -> o.threads = Args.positive(args, ++i, a);
                    case "--scenes" -> o.scenes = List.of(Args.value(args, ++i, a).split(","));
                    case "--samples" -> o.samples = Arrays.stream(Args.value(args, ++i, a).split(","))
                            .map(s -> Args.positive(new String[] {s}, 0, "--samples")).toList();
                    case "--out" -> o.out = Path.of(Args.value(args, ++i, a));
                    case "--work" -> o.work = Path.of(Args.value(args, ++i, a));
                    case "--scenes-dir" -> o.scenesDir = Path.of(Args.value(args, ++i, a));
                    case "--studio-jar" -> o.studioJar = Path.of(Args.value(args, ++i, a));
                    case "--launcher" -> {
                        String value = Args.value(args, ++i, a);
                        o.launcher = value.equals("none") ? null : Path.of(value);
                    }
                    case "--povray" -> o.povray = Path.of(Args.value(args, ++i, a));
                    case "--sunflow-jar" -> o.sunflowJar = Path.of(Args.value(args, ++i, a));
                    case "--java" -> o.java = Path.of(Args.value(args, ++i, a));
                    default -> throw new IllegalArgumentException("unknown argument " + a);
                }
            }
            o.samples.forEach(Renderers::checkSamples);
            List<String> names = new ArrayList<>();
            for (String scene : o.scenes) {
                String name = sceneName(scene);
                if (isSceneFile(scene) ? !Files.isRegularFile(Path.of(scene)) || name.isEmpty()
                        : !SCENE_FILES.containsKey(scene)) {
                    throw new IllegalArgumentException("unknown scene '" + scene + "'; the scenes are "
                            + String.join(", ", SCENE_FILES.keySet()) + ", or a scene file (.json)");
                }
                if (names.contains(name)) {
                    throw new IllegalArgumentException("two scenes named '" + name + "' would share one folder and one row");
                }
                names.add(name);
            }
            return o;
        }
    }
}

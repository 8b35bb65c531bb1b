import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.net.http.WebSocket;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

/**
 * A benchmark of the live view ({@code /api/preview}) of a running, warm Ray Studio server: how soon
 * an edit shows, how smoothly a drag plays, and whether the last frame is the render itself. It
 * speaks the live view's protocol at one view size (640x480 unless told) on every example scene
 * ({@code scenes/*.json}) and on three generated ones: {@code spheres-10k} (10,000 spheres),
 * {@code glass-mirrors} (glass spheres between two mirrors, three lights) and {@code mesh-50k} (a
 * smooth torus of 50,000 triangles sent inline as OBJ, 3.4 MB of message).
 *
 * <pre>
 * java scripts/LiveViewBench.java --url http://127.0.0.1:8080 [--scenes scenes] [--width 640]
 *      [--height 480] [--edits 20] [--drag-seconds 5] [--only NAME] [--warmup 3] [--timeout-seconds 120]
 *      [--protocol patch|whole|both] [--rounds 1]
 * </pre>
 *
 * Each view's first revision is the whole scene; with {@code --protocol patch} (the default, as the
 * editor sends) every later one is an RFC 6902 patch to the revision before it that replaces the
 * moved object's position, with {@code whole} the whole scene again; {@code both} measures each
 * scene both ways on views of their own, in an order that alternates from round to round
 * ({@code --rounds}), so that the two are compared on the same server in the same minutes. A mesh
 * a scene names by {@code file} (an OBJ beside it) is sent inline, as {@code obj}, so that
 * {@code --scenes} may name a folder of held-out scenes with their meshes in files.
 *
 * Per scene, on one WebSocket (an edit is a small move of one object, a new revision):
 * <ol>
 * <li>warm-up: {@code --warmup} revisions, each to its final frame, not counted;
 * <li>edits at rest: {@code --edits} revisions, each sent once the one before has shown its final
 *     frame; timed from before sending the message to the arrival of the revision's first frame,
 *     of its first full-size one-sample frame and of its final frame;
 * <li>edits while refining: {@code --edits} revisions, each sent as soon as the one before has shown
 *     its full-size one-sample frame, while the server renders its final pass (as an editor's user
 *     edits): the same figures, now including stopping the render in hand;
 * <li>a drag: a revision every 33 ms for {@code --drag-seconds}, moving the object a little each
 *     time (a tick that finds the previous message still being sent is skipped and counted):
 *     frames of any revision arriving within the drag, per second, and each one's age (from sending
 *     its revision to its arrival);
 * <li>the final frame of the last edit at rest, decoded, against {@code POST /api/render} of the same
 *     scene with {@code image.width}, {@code image.height} and {@code image.format} set to the view's
 *     size and PNG: every pixel must be equal.
 * </ol>
 * Targets (issue 45's): first frame at most 50 ms median and 150 ms p95; first full-size one-sample
 * frame at most 150 ms median (both for edits at rest and while refining); during a drag at least 24
 * frames/s and frame age at most 100 ms p95; identical final pixels. Percentiles are nearest-rank. It prints a
 * table per scene, a summary, and PASS or FAIL; exit code 0 when every check passed, 1 when one
 * failed (a target missed, a mismatch, a problem answer, a timeout, a lost connection), 2 for bad
 * arguments. Each frame header's {@code millis} (the server's time from having the whole message to
 * sending the frame) is reported beside the client's time, so that the difference, sending the
 * message and receiving the frame, shows. No dependencies: JDK 17's source launcher, java.net.http
 * and javax.imageio.
 */
public final class LiveViewBench {

    static final double FIRST_FRAME_MEDIAN_MS = 50, FIRST_FRAME_P95_MS = 150, FULL_FRAME_MEDIAN_MS = 150;
    static final double DRAG_MIN_FPS = 24, DRAG_AGE_P95_MS = 100;
    static final long DRAG_PERIOD_NANOS = 33_000_000;
    /** An edit moves the object by up to this share of its distance from the camera, a drag by up to this. */
    static final double EDIT_AMPLITUDE = 0.02, DRAG_AMPLITUDE = 0.05;
    /** Revisions for one back-and-forth of an edit sequence, and ticks for one of a drag (2 s). */
    static final int EDIT_PERIOD = 8, DRAG_PERIOD_TICKS = 60;
    static final int POST_ATTEMPTS = 5;

    record Options(URI url, Path scenes, int width, int height, int edits, double dragSeconds, String only, int warmup,
                   int timeoutSeconds, List<String> protocols, int rounds) {

        static Options parse(String[] args) {
            Map<String, String> given = new LinkedHashMap<>();
            for (int i = 0; i < args.length; i += 2) {
                if (!args[i].startsWith("--") || i + 1 >= args.length) {
                    throw new IllegalArgumentException("expected --name value pairs, got " + String.join(" ", args));
                }
                given.put(args[i].substring(2), args[i + 1]);
            }
            URI url = URI.create(take(given, "url", "http://127.0.0.1:8080"));
            if (!"http".equals(url.getScheme()) && !"https".equals(url.getScheme())) {
                throw new IllegalArgumentException("--url must be http://host:port or https://host:port");
            }
            Options options = new Options(url, Path.of(take(given, "scenes", "scenes")),
                    positive(take(given, "width", "640"), "width"), positive(take(given, "height", "480"), "height"),
                    positive(take(given, "edits", "20"), "edits"), Double.parseDouble(take(given, "drag-seconds", "5")),
                    given.remove("only"), Integer.parseInt(take(given, "warmup", "3")),
                    positive(take(given, "timeout-seconds", "120"), "timeout-seconds"),
                    protocols(take(given, "protocol", "patch")), positive(take(given, "rounds", "1"), "rounds"));
            if (!given.isEmpty()) {
                throw new IllegalArgumentException("unknown options: " + given.keySet());
            }
            if (!(options.dragSeconds > 0) || options.warmup < 0) {
                throw new IllegalArgumentException("--drag-seconds must be positive and --warmup at least 0");
            }
            if (!Files.isDirectory(options.scenes)) {
                throw new IllegalArgumentException("--scenes " + options.scenes + " is not a folder");
            }
            return options;
        }

        /** "whole", "patch", or "both": each scene with the whole scene in every message, and with patches, alternated. */
        private static List<String> protocols(String value) {
            return switch (value) {
                case "whole", "patch" -> List.of(value);
                case "both" -> List.of("whole", "patch");
                default -> throw new IllegalArgumentException("--protocol must be whole, patch or both, got " + value);
            };
        }

        private static int positive(String value, String name) {
            int n = Integer.parseInt(value);
            if (n <= 0) {
                throw new IllegalArgumentException("--" + name + " must be positive, got " + value);
            }
            return n;
        }

        private static String take(Map<String, String> given, String name, String fallback) {
            String value = given.remove(name);
            return value != null ? value : fallback;
        }

        URI preview() {
            return URI.create(url.toString().replaceFirst("^http", "ws").replaceAll("/+$", "") + "/api/preview");
        }

        URI render() {
            return URI.create(url.toString().replaceAll("/+$", "") + "/api/render");
        }
    }

    public static void main(String[] args) throws Exception {
        Options options;
        List<BenchScene> scenes;
        try {
            options = Options.parse(args);
            scenes = scenes(options);
        } catch (IllegalArgumentException | IOException e) {
            System.err.println("error: " + e.getMessage());
            System.exit(2);
            return;
        }
        System.exit(new LiveViewBench(options).run(scenes) ? 0 : 1);
    }

    /** The example scenes in file-name order, then the generated ones; only one with --only. */
    static List<BenchScene> scenes(Options options) throws IOException {
        List<BenchScene> scenes = new ArrayList<>();
        int w = options.width(), h = options.height();
        List<Path> files;
        try (Stream<Path> list = Files.list(options.scenes())) {
            files = list.filter(p -> p.getFileName().toString().endsWith(".json")).sorted().toList();
        }
        for (Path file : files) {
            String name = file.getFileName().toString().replaceFirst("\\.json$", "");
            scenes.add(BenchScene.of(name, inlineFiles(Json.object(Json.parse(Files.readString(file))), file.getParent()), w, h));
        }
        scenes.add(BenchScene.of("spheres-10k", Generated.spheres(10_000), w, h));
        scenes.add(BenchScene.of("glass-mirrors", Generated.glassBetweenMirrors(), w, h));
        scenes.add(BenchScene.of("mesh-50k", Generated.torusMesh(250, 100), w, h));
        if (options.only() != null) {
            List<BenchScene> one = scenes.stream().filter(s -> s.name().equals(options.only())).toList();
            if (one.isEmpty()) {
                throw new IllegalArgumentException("--only " + options.only() + ": no such scene; there are "
                        + scenes.stream().map(BenchScene::name).toList());
            }
            return one;
        }
        return scenes;
    }

    /**
     * The scene with each mesh's {@code file} (an OBJ beside the scene, as the command line reads it)
     * sent inline as {@code obj}, the server's form of it, so that held-out scenes with their meshes
     * in files can be measured as they are.
     */
    static Map<String, Object> inlineFiles(Map<String, Object> scene, Path folder) throws IOException {
        for (Object o : Json.list(scene.getOrDefault("objects", List.of()))) {
            Map<String, Object> object = Json.object(o);
            if ("mesh".equals(object.get("type")) && object.get("file") instanceof String file) {
                Map<String, Object> inlined = new LinkedHashMap<>();
                for (Map.Entry<String, Object> e : object.entrySet()) {
                    if (e.getKey().equals("file")) {
                        inlined.put("obj", Files.readString(folder.resolve(file)));
                    } else {
                        inlined.put(e.getKey(), e.getValue());
                    }
                }
                object.clear();
                object.putAll(inlined);
            }
        }
        return scene;
    }

    private final Options options;
    private final HttpClient http = HttpClient.newBuilder().version(HttpClient.Version.HTTP_1_1)
            .connectTimeout(Duration.ofSeconds(5)).build();

    LiveViewBench(Options options) {
        this.options = options;
    }

    boolean run(List<BenchScene> scenes) {
        System.out.printf("live view %s, view %dx%d, %d edits at rest and %d while refining per scene, a %.1f s drag "
                        + "(a revision every %d ms), %d warm-up revisions%n", options.preview(), options.width(),
                options.height(), options.edits(), options.edits(), options.dragSeconds(),
                DRAG_PERIOD_NANOS / 1_000_000, options.warmup());
        System.out.println(machine());
        List<Result> results = new ArrayList<>();
        for (BenchScene scene : scenes) {
            for (int round = 0; round < options.rounds(); round++) {
                List<String> order = new ArrayList<>(options.protocols());
                if (round % 2 == 1) {
                    Collections.reverse(order); // alternated, so that neither always runs on a warmer server
                }
                for (String protocol : order) {
                    Result result = new Result(scene, protocol, round + 1);
                    try {
                        measure(scene, result);
                    } catch (Exception e) {
                        result.fail("stopped: " + e);
                    }
                    result.print();
                    results.add(result);
                }
            }
        }
        return summary(results);
    }

    // ---- one scene

    private void measure(BenchScene scene, Result result) throws Exception {
        long timeout = TimeUnit.SECONDS.toNanos(options.timeoutSeconds());
        try (View view = new View(http, options.preview(), scene.width(), scene.height())) {
            int revision = 0;
            for (int i = 0; i < options.warmup(); i++) {
                view.send(++revision, message(scene, result.protocol, revision, scene.editOffset(revision)));
                view.await(revision, View.Until.FINAL, timeout);
            }
            double[] checked = null;
            for (int i = 0; i < options.edits(); i++) {
                double[] at = scene.editOffset(++revision);
                Sent sent = view.send(revision, message(scene, result.protocol, revision, at));
                result.atRest.add(view.await(revision, View.Until.FINAL, timeout).relativeTo(sent));
                checked = at;
            }
            result.finalFrame = view.lastFinal;
            for (int i = 0; i < options.edits(); i++) {
                Sent sent = view.send(++revision, message(scene, result.protocol, revision, scene.editOffset(revision)));
                result.refining.add(view.await(revision, View.Until.FULL_SIZE, timeout).relativeTo(sent));
            }
            view.await(revision, View.Until.FINAL, timeout);
            drag(scene, view, revision, result, timeout);
            result.check = compare(scene, checked, result.finalFrame);
        }
    }

    private void drag(BenchScene scene, View view, int revision, Result result, long timeout) throws Exception {
        long duration = (long) (options.dragSeconds() * 1e9);
        view.frames.clear();
        long start = System.nanoTime(), end = start + duration;
        int tick = 0;
        for (;;) {
            long due = start + tick * DRAG_PERIOD_NANOS;
            if (due >= end) {
                break;
            }
            long now;
            while ((now = System.nanoTime()) < due) {
                LockSupport.parkNanos(due - now); // pacing the drag, not waiting for the server
            }
            if (now - due >= DRAG_PERIOD_NANOS) { // the last send took longer than a tick
                int caughtUp = (int) ((now - start) / DRAG_PERIOD_NANOS);
                result.dragSkipped += caughtUp - tick;
                tick = caughtUp;
                continue;
            }
            revision++;
            result.dragSending.add(view.send(revision, message(scene, result.protocol, revision, scene.dragOffset(tick))).millis());
            tick++;
        }
        view.await(revision, View.Until.FINAL, timeout);
        synchronized (view.frames) {
            for (Frame frame : view.frames) {
                if (frame.arrived() <= end) {
                    result.dragFrames.add(frame);
                    result.dragAges.add((frame.arrived() - view.sentAt(frame.revision())) / 1e6);
                }
            }
        }
        result.dragSeconds = duration / 1e9;
    }

    /**
     * Revision {@code revision}'s message: the whole scene, or (protocol "patch", after a view's first
     * revision) a patch to the revision before it that moves the object, as the editor sends it.
     */
    private static String message(BenchScene scene, String protocol, int revision, double[] offset) {
        String size = "{\"revision\":" + revision + ",\"width\":%d,\"height\":%d,".formatted(scene.width, scene.height);
        if (protocol.equals("patch") && revision > 1) {
            return size + "\"base\":" + (revision - 1) + ",\"patch\":[{\"op\":\"replace\",\"path\":\"" + scene.movedPath()
                    + "\",\"value\":[" + offset[0] + "," + offset[1] + "," + offset[2] + "]}]}";
        }
        return size + "\"scene\":" + scene.json(offset, false) + "}";
    }

    // ---- the final frame against POST /api/render

    private String compare(BenchScene scene, double[] offset, Frame frame) throws Exception {
        if (frame == null || frame.image() == null) {
            return "no final frame to compare";
        }
        byte[] rendered = null;
        for (int attempt = 1; rendered == null; attempt++) {
            HttpResponse<byte[]> response = http.send(HttpRequest.newBuilder(options.render())
                    .header("Content-Type", "application/json").timeout(Duration.ofSeconds(options.timeoutSeconds()))
                    .POST(HttpRequest.BodyPublishers.ofString(scene.json(offset, true))).build(),
                    HttpResponse.BodyHandlers.ofByteArray());
            if (response.statusCode() == 200) {
                rendered = response.body();
            } else if (response.statusCode() == 503 && attempt < POST_ATTEMPTS) {
                long seconds = response.headers().firstValueAsLong("Retry-After").orElse(1);
                Thread.sleep(TimeUnit.SECONDS.toMillis(Math.min(seconds, 10))); // the server asked for this wait
            } else {
                return "POST /api/render answered " + response.statusCode() + ": "
                        + new String(response.body(), StandardCharsets.UTF_8);
            }
        }
        BufferedImage live = ImageIO.read(new ByteArrayInputStream(frame.image()));
        BufferedImage render = ImageIO.read(new ByteArrayInputStream(rendered));
        if (live == null || render == null) {
            return "could not decode " + (live == null ? "the final frame" : "the render");
        }
        if (live.getWidth() != render.getWidth() || live.getHeight() != render.getHeight()) {
            return "sizes differ: frame %dx%d, render %dx%d".formatted(live.getWidth(), live.getHeight(),
                    render.getWidth(), render.getHeight());
        }
        int w = live.getWidth(), h = live.getHeight();
        int[] a = live.getRGB(0, 0, w, h, null, 0, w), b = render.getRGB(0, 0, w, h, null, 0, w);
        int differing = 0, worst = 0;
        for (int i = 0; i < a.length; i++) {
            if (a[i] != b[i]) {
                differing++;
                for (int shift = 0; shift < 32; shift += 8) {
                    worst = Math.max(worst, Math.abs(((a[i] >>> shift) & 0xff) - ((b[i] >>> shift) & 0xff)));
                }
            }
        }
        return differing == 0 ? null
                : "%d of %d pixels differ, by up to %d/255 in a channel".formatted(differing, a.length, worst);
    }

    // ---- summary

    private boolean summary(List<Result> results) {
        System.out.println();
        System.out.println("summary (ms; first frame and full-size frame: median/p95, at rest | while refining)");
        System.out.printf("%-32s %15s %15s %15s %15s %8s %9s %-10s %s%n", "scene", "first, rest", "first, refining",
                "full, rest", "full, refining", "drag f/s", "age p95", "final", "");
        List<String> failures = new ArrayList<>();
        for (Result r : results) {
            System.out.printf(Locale.ROOT, "%-32s %15s %15s %15s %15s %8s %9s %-10s %s%n", r.label(),
                    pair(r.firsts(r.atRest)), pair(r.firsts(r.refining)), pair(r.fulls(r.atRest)),
                    pair(r.fulls(r.refining)), decimal(r.fps(), 1), decimal(pct(r.dragAges, 95), 0),
                    r.check == null ? "identical" : r.check.equals("not checked") ? "-" : "MISMATCH",
                    r.failures.isEmpty() ? "ok" : "FAIL");
            r.failures.forEach(f -> failures.add(r.label() + ": " + f));
        }
        System.out.println(machine());
        System.out.println();
        if (failures.isEmpty()) {
            System.out.println("PASS: every scene within the targets, every final frame identical to POST /api/render");
            return true;
        }
        System.out.println("FAIL: " + failures.size() + " checks failed");
        failures.forEach(f -> System.out.println("  " + f));
        return false;
    }

    /** The cores and load of this machine (the server's too, on loopback): wall times depend on them. */
    private static String machine() {
        var os = java.lang.management.ManagementFactory.getOperatingSystemMXBean();
        return String.format(Locale.ROOT, "this machine: %d cores, load average %.2f", os.getAvailableProcessors(),
                os.getSystemLoadAverage());
    }

    private static String pair(double[] values) {
        return decimal(pct(values, 50), 0) + "/" + decimal(pct(values, 95), 0);
    }

    /** A figure with so many decimals, or "-" for none. */
    static String decimal(double value, int decimals) {
        return Double.isNaN(value) ? "-" : String.format(Locale.ROOT, "%." + decimals + "f", value);
    }

    static double pct(List<Double> values, int percent) {
        return pct(values.stream().mapToDouble(Double::doubleValue).toArray(), percent);
    }

    /** Nearest-rank percentile; NaN for no values. */
    static double pct(double[] values, int percent) {
        if (values.length == 0) {
            return Double.NaN;
        }
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int rank = (int) Math.ceil(percent / 100.0 * sorted.length);
        return sorted[Math.max(0, rank - 1)];
    }

    // ---- what one revision showed

    /** A frame as received: its header, when it arrived (System.nanoTime), and the image if it is final. */
    record Frame(long revision, int pass, int width, int height, int samplesPerPixel, boolean last, String format,
                 long serverMillis, long arrived, byte[] image) {
    }

    /** When sending a revision's message began and ended (System.nanoTime). */
    record Sent(long start, long done) {
        double millis() {
            return (done - start) / 1e6;
        }
    }

    /**
     * One revision's frames, timed from when its message began to be sent (ms).
     *
     * @param sending           how long sending the message took (until the last byte was written)
     * @param serverFirstMillis the first frame's header millis: from the server having the whole message to the frame
     */
    record Edit(double sending, double first, double fullSize, double last, long serverFirstMillis, List<Frame> frames,
                double[] passMillis) {
    }

    /** Collects one revision's frames up to a point. */
    static final class EditFrames {
        final List<Frame> frames = new ArrayList<>();
        long first = -1, fullSize = -1, last = -1;

        Edit relativeTo(Sent sent) {
            long from = sent.start();
            double[] passes = frames.stream().mapToDouble(f -> (f.arrived() - from) / 1e6).toArray();
            return new Edit(sent.millis(), (first - from) / 1e6, fullSize < 0 ? Double.NaN : (fullSize - from) / 1e6,
                    last < 0 ? Double.NaN : (last - from) / 1e6, frames.get(0).serverMillis(), List.copyOf(frames),
                    passes);
        }
    }

    /** One live view: sends revisions, receives frames and problems on the client's thread, in order. */
    static final class View implements WebSocket.Listener, AutoCloseable {

        enum Until { FULL_SIZE, FINAL }

        /** A frame, a problem ({@code text}) or the end of the connection ({@code closed}). */
        private record Event(Frame frame, String text, String closed) {
        }

        private final BlockingQueue<Event> events = new LinkedBlockingQueue<>();
        private final Map<Long, Long> sent = new ConcurrentHashMap<>();
        /** Every frame received since last cleared (the drag's). */
        final List<Frame> frames = Collections.synchronizedList(new ArrayList<>());
        private final ByteArrayOutputStream binary = new ByteArrayOutputStream();
        private final StringBuilder text = new StringBuilder();
        private final WebSocket socket;
        private final int width, height;
        Frame lastFinal;

        View(HttpClient http, URI uri, int width, int height) throws Exception {
            this.width = width;
            this.height = height;
            socket = http.newWebSocketBuilder().connectTimeout(Duration.ofSeconds(10)).buildAsync(uri, this)
                    .get(30, TimeUnit.SECONDS);
        }

        /** Sends a revision; its times count from when sending began. */
        Sent send(long revision, String message) throws Exception {
            long start = System.nanoTime();
            sent.put(revision, start);
            socket.sendText(message, true).get(60, TimeUnit.SECONDS);
            return new Sent(start, System.nanoTime());
        }

        long sentAt(long revision) {
            return sent.get(revision);
        }

        /**
         * Waits for a revision's full-size one-sample frame, or its final frame, skipping older
         * revisions' frames.
         *
         * @throws IllegalStateException on a problem, a closed connection or no such frame in time
         */
        EditFrames await(long revision, Until until, long timeoutNanos) throws InterruptedException {
            long deadline = System.nanoTime() + timeoutNanos;
            EditFrames edit = new EditFrames();
            for (;;) {
                Event event = events.poll(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
                if (event == null) {
                    throw new IllegalStateException("revision " + revision + ": no " + until.name().toLowerCase(Locale.ROOT)
                            + " frame within " + TimeUnit.NANOSECONDS.toSeconds(timeoutNanos) + " s; frames so far "
                            + edit.frames.stream().map(f -> f.pass() + ":" + f.width() + "x" + f.height()).toList());
                }
                if (event.closed() != null) {
                    throw new IllegalStateException("the live view closed: " + event.closed());
                }
                if (event.text() != null) {
                    throw new IllegalStateException("a problem: " + event.text());
                }
                Frame frame = event.frame();
                if (frame.revision() != revision) {
                    continue; // an earlier revision's, still under way when this one was sent
                }
                edit.frames.add(frame);
                if (edit.first < 0) {
                    edit.first = frame.arrived();
                }
                boolean fullSize = frame.samplesPerPixel() == 1 && frame.width() == width && frame.height() == height;
                if (edit.fullSize < 0 && (fullSize || frame.last())) {
                    edit.fullSize = frame.arrived(); // a scene of one sample has no pass between the last and the full size
                }
                if (frame.last()) {
                    edit.last = frame.arrived();
                    lastFinal = frame;
                    return edit;
                }
                if (until == Until.FULL_SIZE && edit.fullSize >= 0) {
                    return edit;
                }
            }
        }

        @Override
        public CompletionStage<?> onBinary(WebSocket webSocket, ByteBuffer data, boolean last) {
            byte[] bytes = new byte[data.remaining()];
            data.get(bytes);
            binary.writeBytes(bytes);
            if (last) {
                long arrived = System.nanoTime();
                byte[] message = binary.toByteArray();
                binary.reset();
                int length = ByteBuffer.wrap(message, 0, 4).getInt();
                Map<String, Object> h = Json.object(Json.parse(new String(message, 4, length, StandardCharsets.UTF_8)));
                boolean isFinal = Boolean.TRUE.equals(h.get("final"));
                Frame frame = new Frame(Json.number(h, "revision"), (int) Json.number(h, "pass"),
                        (int) Json.number(h, "width"), (int) Json.number(h, "height"),
                        (int) Json.number(h, "samplesPerPixel"), isFinal, (String) h.get("format"),
                        Json.number(h, "millis"), arrived, isFinal ? Arrays.copyOfRange(message, 4 + length, message.length) : null);
                frames.add(frame);
                events.add(new Event(frame, null, null));
            }
            webSocket.request(1);
            return null;
        }

        @Override
        public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
            text.append(data);
            if (last) {
                events.add(new Event(null, text.toString(), null));
                text.setLength(0);
            }
            webSocket.request(1);
            return null;
        }

        @Override
        public CompletionStage<?> onClose(WebSocket webSocket, int statusCode, String reason) {
            events.add(new Event(null, null, statusCode + " " + reason));
            return null;
        }

        @Override
        public void onError(WebSocket webSocket, Throwable error) {
            events.add(new Event(null, null, error.toString()));
        }

        @Override
        public void close() {
            socket.sendClose(WebSocket.NORMAL_CLOSURE, "done").orTimeout(5, TimeUnit.SECONDS)
                    .exceptionally(e -> null).join();
            socket.abort();
        }
    }

    // ---- one scene's figures and their report

    static final class Result {
        final BenchScene scene;
        final List<Edit> atRest = new ArrayList<>(), refining = new ArrayList<>();
        final List<Frame> dragFrames = new ArrayList<>();
        final List<Double> dragAges = new ArrayList<>(), dragSending = new ArrayList<>();
        final List<String> failures = new ArrayList<>();
        int dragSkipped;
        double dragSeconds = Double.NaN;
        Frame finalFrame;
        /** null when the final frame matched the render. */
        String check = "not checked";

        /** "whole" or "patch": how every revision after a view's first was sent. */
        final String protocol;
        final int round;

        Result(BenchScene scene, String protocol, int round) {
            this.scene = scene;
            this.protocol = protocol;
            this.round = round;
        }

        /** The scene, with how its revisions were sent. */
        String label() {
            return scene.name() + " (" + protocol + (round > 1 ? ", round " + round : "") + ")";
        }

        void fail(String failure) {
            failures.add(failure);
        }

        double[] firsts(List<Edit> edits) {
            return edits.stream().mapToDouble(Edit::first).toArray();
        }

        double[] fulls(List<Edit> edits) {
            return edits.stream().mapToDouble(Edit::fullSize).toArray();
        }

        double fps() {
            return dragFrames.size() / dragSeconds;
        }

        void print() {
            System.out.println();
            System.out.printf(Locale.ROOT, "== %s: %,d objects, %s message, final pass %s%n", label(),
                    scene.objects(), bytes(scene.json(scene.editOffset(0), false).length()), finalPass());
            System.out.printf("%-44s %9s %9s   %s%n", "", "median", "p95", "target");
            if (!atRest.isEmpty()) {
                row("sending the message, edit at rest", atRest.stream().mapToDouble(Edit::sending).toArray(),
                        Double.NaN, Double.NaN);
                row("first frame, edit at rest", firsts(atRest), FIRST_FRAME_MEDIAN_MS, FIRST_FRAME_P95_MS);
                row("  of which the server (header millis)",
                        atRest.stream().mapToDouble(Edit::serverFirstMillis).toArray(), Double.NaN, Double.NaN);
                row("full-size 1-sample frame, edit at rest", fulls(atRest), FULL_FRAME_MEDIAN_MS, Double.NaN);
                row("final frame, edit at rest", atRest.stream().mapToDouble(Edit::last).toArray(), Double.NaN,
                        Double.NaN);
                System.out.println("  passes at rest, median arrival: " + passes(atRest));
            }
            if (!refining.isEmpty()) {
                row("sending the message, while refining", refining.stream().mapToDouble(Edit::sending).toArray(),
                        Double.NaN, Double.NaN);
                row("first frame, edit while refining", firsts(refining), FIRST_FRAME_MEDIAN_MS, FIRST_FRAME_P95_MS);
                row("  of which the server (header millis)",
                        refining.stream().mapToDouble(Edit::serverFirstMillis).toArray(), Double.NaN, Double.NaN);
                row("full-size 1-sample frame, while refining", fulls(refining), FULL_FRAME_MEDIAN_MS, Double.NaN);
            }
            if (!Double.isNaN(dragSeconds)) {
                Map<Integer, Integer> byPass = new TreeMap<>();
                dragFrames.forEach(f -> byPass.merge(f.pass(), 1, Integer::sum));
                long shown = dragFrames.stream().mapToLong(Frame::revision).distinct().count();
                System.out.printf(Locale.ROOT, "%-44s %9.1f %9s   >= %.0f  %s%n", "drag: frames per second", fps(), "",
                        DRAG_MIN_FPS, fps() >= DRAG_MIN_FPS ? "ok" : "MISSED");
                if (fps() < DRAG_MIN_FPS) {
                    fail(String.format(Locale.ROOT, "drag: %.1f frames/s, target >= %.0f", fps(), DRAG_MIN_FPS));
                }
                row("drag: frame age", dragAges.stream().mapToDouble(Double::doubleValue).toArray(), Double.NaN,
                        DRAG_AGE_P95_MS);
                System.out.printf(Locale.ROOT, "  drag: %d revisions sent in %.1f s (sending took %.1f ms median, "
                                + "%.1f p95; %d ticks skipped while sending), %d frames of %d revisions; frames by pass "
                                + "%s%n", dragSending.size(), dragSeconds, pct(dragSending, 50), pct(dragSending, 95),
                        dragSkipped, dragFrames.size(), shown, byPass);
            }
            if (check == null) {
                System.out.printf("final frame against POST /api/render: identical (%dx%d)%n", finalFrame.width(),
                        finalFrame.height());
            } else if (!failures.isEmpty() && failures.get(0).startsWith("stopped")) {
                System.out.println("final frame against POST /api/render: not checked");
            } else {
                System.out.println("final frame against POST /api/render: MISMATCH: " + check);
                fail("final frame: " + check);
            }
            failures.stream().filter(f -> f.startsWith("stopped")).forEach(f -> System.out.println("  " + f));
        }

        private void row(String label, double[] values, double medianTarget, double p95Target) {
            double median = pct(values, 50), p95 = pct(values, 95);
            String figures = String.format(Locale.ROOT, "%9s %9s", decimal(median, 1), decimal(p95, 1));
            List<String> targets = new ArrayList<>();
            boolean ok = true;
            if (!Double.isNaN(medianTarget)) {
                targets.add(String.format(Locale.ROOT, "median <= %.0f", medianTarget));
                ok &= median <= medianTarget;
            }
            if (!Double.isNaN(p95Target)) {
                targets.add(String.format(Locale.ROOT, "p95 <= %.0f", p95Target));
                ok &= p95 <= p95Target;
            }
            String verdict = targets.isEmpty() ? "" : ok ? "ok" : "MISSED";
            System.out.printf(Locale.ROOT, "%-44s %s   %s  %s%n", label, figures, String.join(", ", targets), verdict);
            if (!ok) {
                fail(values.length == 0 ? label.trim() + ": none"
                        : String.format(Locale.ROOT, "%s: median %.1f ms, p95 %.1f ms; target %s", label.trim(), median,
                        p95, String.join(", ", targets)));
            }
        }

        private String finalPass() {
            if (atRest.isEmpty()) {
                return "?";
            }
            Frame last = atRest.get(0).frames().get(atRest.get(0).frames().size() - 1);
            return "%dx%d at %d samples/pixel".formatted(last.width(), last.height(), last.samplesPerPixel());
        }

        /** "1 80x60 12 ms, 2 160x120 20 ms, ..." over the edits whose passes were all shown. */
        private String passes(List<Edit> edits) {
            Map<Integer, List<Double>> times = new TreeMap<>();
            Map<Integer, String> sizes = new HashMap<>();
            for (Edit edit : edits) {
                for (int i = 0; i < edit.frames().size(); i++) {
                    Frame f = edit.frames().get(i);
                    times.computeIfAbsent(f.pass(), k -> new ArrayList<>()).add(edit.passMillis()[i]);
                    sizes.put(f.pass(), f.width() + "x" + f.height() + (f.samplesPerPixel() > 1
                            ? "x" + f.samplesPerPixel() : ""));
                }
            }
            List<String> out = new ArrayList<>();
            times.forEach((pass, ms) -> out.add(String.format(Locale.ROOT, "%d %s %.0f ms", pass, sizes.get(pass),
                    pct(ms, 50))));
            return String.join(", ", out);
        }
    }

    private static String bytes(long n) {
        return n < 10_000 ? n + " B" : n < 10_000_000 ? String.format(Locale.ROOT, "%.1f kB", n / 1e3)
                : String.format(Locale.ROOT, "%.1f MB", n / 1e6);
    }

    // ---- scenes and their edits

    /**
     * A scene with one object that edits move: its JSON, cut around that object's position, so that
     * a revision costs the client a few string appends even with a 3 MB mesh inline.
     *
     * @param name    the file's name without .json, or the generated scene's
     * @param origin  the moved object's position before any edit
     * @param step    the length of an edit's largest move: a share of the object's distance from the camera
     * @param live    the scene's JSON before and after the moved position, as the live view gets it
     * @param render  the same with image.width, image.height and image.format set, for POST /api/render
     */
    record BenchScene(String name, int objects, double[] origin, double step, String[] live, String[] render,
                      int width, int height, String movedPath) {

        private static final String MARK = "\u0000position\u0000";

        static BenchScene of(String name, Map<String, Object> scene, int width, int height) {
            List<Object> objects = Json.list(scene.get("objects"));
            Map<String, Object> moved = null;
            String field = null;
            double[] origin = null;
            int movedIndex = -1;
            for (Object o : objects) {
                movedIndex++;
                Map<String, Object> object = Json.object(o);
                String type = String.valueOf(object.get("type"));
                field = switch (type) {
                    case "sphere", "box" -> "center";
                    case "mesh" -> "position";
                    default -> null;
                };
                if (field != null) {
                    moved = object;
                    // the defaults of the scene format, for an object that leaves its position out
                    origin = object.containsKey(field) ? Json.vector(object.get(field))
                            : type.equals("sphere") ? new double[] {0, 1, 0}
                            : type.equals("box") ? new double[] {0, 0.5, 0} : new double[] {0, 0, 0};
                    break;
                }
            }
            if (moved == null) {
                throw new IllegalArgumentException(name + ": no sphere, box or mesh to move");
            }
            Map<String, Object> camera = scene.containsKey("camera") ? Json.object(scene.get("camera")) : Map.of();
            double[] eye = camera.containsKey("position") ? Json.vector(camera.get("position")) : new double[] {0, 2, 8};
            double distance = Math.sqrt(Math.pow(origin[0] - eye[0], 2) + Math.pow(origin[1] - eye[1], 2)
                    + Math.pow(origin[2] - eye[2], 2));
            Object before = moved.get(field);
            moved.put(field, MARK);
            String live = Json.write(scene);
            Object image = scene.get("image");
            Map<String, Object> sized = new LinkedHashMap<>(image != null ? Json.object(image) : Map.of());
            sized.put("width", width);
            sized.put("height", height);
            sized.put("format", "png");
            scene.put("image", sized);
            String render = Json.write(scene);
            scene.put("image", image);
            moved.put(field, before);
            return new BenchScene(name, objects.size(), origin, distance, cut(live), cut(render), width, height,
                    "/objects/" + movedIndex + "/" + field);
        }

        private static String[] cut(String json) {
            String quoted = Json.write(MARK);
            int at = json.indexOf(quoted);
            return new String[] {json.substring(0, at), json.substring(at + quoted.length())};
        }

        /** The position for edit number n: back and forth along x, a little each time. */
        double[] editOffset(int n) {
            return along(triangle(n, EDIT_PERIOD) * EDIT_AMPLITUDE * step);
        }

        /** The position for drag tick n. */
        double[] dragOffset(int n) {
            return along(triangle(n, DRAG_PERIOD_TICKS) * DRAG_AMPLITUDE * step);
        }

        private double[] along(double dx) {
            return new double[] {origin[0] + dx, origin[1], origin[2]};
        }

        /** -1 to 1 and back over a period, never the same value twice in a row. */
        private static double triangle(int n, int period) {
            double phase = ((n % period) + 0.5) / period;
            return phase < 0.5 ? 4 * phase - 1 : 3 - 4 * phase;
        }

        /** The scene's JSON with the moved object at a position; with the view's size and PNG for a render. */
        String json(double[] at, boolean forRender) {
            String[] parts = forRender ? render : live;
            return parts[0] + "[" + at[0] + "," + at[1] + "," + at[2] + "]" + parts[1];
        }
    }

    // ---- generated scenes

    static final class Generated {

        /** n spheres in a 8 x 3 x 6 m box above a floor, a larger mirror sphere in front (the one moved). */
        static Map<String, Object> spheres(int n) {
            Random random = new Random(1);
            String[] materials = {"chalk", "plastic", "metal"};
            List<Object> objects = new ArrayList<>();
            objects.add(object("sphere", "center", List.of(0.0, 0.8, 2.5), "radius", 0.6, "material",
                    Map.of("type", "mirror")));
            double radius = 0.07;
            for (int i = 1; i < n; i++) {
                List<Double> center = List.of(round(-4 + 8 * random.nextDouble()), round(radius + 3 * random.nextDouble()),
                        round(-4 + 6 * random.nextDouble()));
                objects.add(object("sphere", "center", center, "radius", radius, "material",
                        Map.of("type", materials[i % 3], "color", colour(random))));
            }
            objects.add(object("plane", "material", Map.of("type", "chalk", "color", "#b0b0b0")));
            return scene("spheres-10k", Map.of("position", List.of(0, 3, 9), "lookAt", List.of(0, 1, 0), "fov", 45),
                    Map.of("sampler", "sobol", "samples", 16, "maxDepth", 4), lights(2), objects);
        }

        /** Five glass spheres of several tints between two facing mirrors, on a floor, three lights. */
        static Map<String, Object> glassBetweenMirrors() {
            List<Object> objects = new ArrayList<>();
            String[] tints = {"#ffffff", "#d8f0e0", "#f0d8d8", "#d8e0f8", "#fff0c0"};
            for (int i = 0; i < tints.length; i++) {
                objects.add(object("sphere", "center", List.of(-2.0 + i, 0.5 + 0.15 * (i % 2), 0.3 * (i % 3)),
                        "radius", 0.45, "material", Map.of("type", "glass", "color", tints[i], "ior", 1.4 + 0.05 * i)));
            }
            objects.add(object("box", "center", List.of(-3.2, 1.5, 0.0), "size", List.of(0.05, 3, 6), "material",
                    Map.of("type", "mirror", "color", "#e8f0ff")));
            objects.add(object("box", "center", List.of(3.2, 1.5, 0.0), "size", List.of(0.05, 3, 6), "material",
                    Map.of("type", "mirror", "color", "#fff8e8")));
            objects.add(object("box", "center", List.of(0, 1.5, -3.0), "size", List.of(6.4, 3, 0.05), "material",
                    Map.of("type", "chalk", "color", "#303848")));
            objects.add(object("plane", "material", Map.of("type", "chalk", "color", "#a09a90")));
            return scene("glass-mirrors", Map.of("position", List.of(0, 2.2, 6.5), "lookAt", List.of(0, 0.8, 0), "fov", 50),
                    Map.of("sampler", "jittered", "samples", 16, "maxDepth", 8), lights(3), objects);
        }

        /** A smooth torus of 2 x major x minor triangles (250 x 100: 50,000), inline OBJ with normals, standing up. */
        static Map<String, Object> torusMesh(int major, int minor) {
            double r1 = 1.0, r2 = 0.35;
            StringBuilder obj = new StringBuilder();
            for (int i = 0; i < major; i++) {
                double u = 2 * Math.PI * i / major;
                for (int j = 0; j < minor; j++) {
                    double v = 2 * Math.PI * j / minor;
                    double nx = Math.cos(v) * Math.cos(u), ny = Math.cos(v) * Math.sin(u), nz = Math.sin(v);
                    obj.append(String.format(Locale.ROOT, "v %.5f %.5f %.5f%nvn %.5f %.5f %.5f%n",
                            r1 * Math.cos(u) + r2 * nx, r1 * Math.sin(u) + r2 * ny, r2 * nz, nx, ny, nz));
                }
            }
            for (int i = 0; i < major; i++) {
                for (int j = 0; j < minor; j++) {
                    int a = i * minor + j + 1, b = ((i + 1) % major) * minor + j + 1;
                    int c = ((i + 1) % major) * minor + (j + 1) % minor + 1, d = i * minor + (j + 1) % minor + 1;
                    obj.append("f ").append(a).append("//").append(a).append(' ').append(b).append("//").append(b)
                            .append(' ').append(c).append("//").append(c).append('\n');
                    obj.append("f ").append(a).append("//").append(a).append(' ').append(c).append("//").append(c)
                            .append(' ').append(d).append("//").append(d).append('\n');
                }
            }
            List<Object> objects = new ArrayList<>();
            objects.add(object("mesh", "obj", obj.toString(), "position", List.of(0.0, 1.4, 0.0), "rotation",
                    List.of(0, 25, 0), "material", Map.of("type", "plastic", "color", "#e0a030")));
            objects.add(object("sphere", "center", List.of(2.0, 0.5, 1.0), "radius", 0.5, "material",
                    Map.of("type", "mirror")));
            objects.add(object("plane", "material", Map.of("type", "chalk", "color", "#d8d8d8")));
            return scene("mesh-50k", Map.of("position", List.of(0, 2.5, 6.5), "lookAt", List.of(0, 1.2, 0), "fov", 45),
                    Map.of("sampler", "sobol", "samples", 16, "maxDepth", 4), lights(2), objects);
        }

        private static Map<String, Object> scene(String name, Map<String, Object> camera, Map<String, Object> render,
                                                 List<Object> lights, List<Object> objects) {
            Map<String, Object> scene = new LinkedHashMap<>();
            scene.put("name", name);
            scene.put("image", Map.of("width", 800, "height", 600, "format", "png"));
            scene.put("camera", camera);
            scene.put("render", render);
            scene.put("lights", lights);
            scene.put("objects", objects);
            return scene;
        }

        private static List<Object> lights(int n) {
            List<Object> lights = new ArrayList<>();
            double[][] at = {{4, 7, 5}, {-5, 4, 3}, {0, 2.5, 4}};
            String[] colours = {"#ffffff", "#a8c0ff", "#ffd8a8"};
            for (int i = 0; i < n; i++) {
                lights.add(object("point", "position", List.of(at[i][0], at[i][1], at[i][2]), "color", colours[i],
                        "intensity", i == 0 ? 0.9 : 0.4));
            }
            return lights;
        }

        private static Map<String, Object> object(String type, Object... fields) {
            Map<String, Object> object = new LinkedHashMap<>();
            object.put("type", type);
            for (int i = 0; i < fields.length; i += 2) {
                object.put((String) fields[i], fields[i + 1]);
            }
            return object;
        }

        private static double round(double x) {
            return Math.round(x * 1e4) / 1e4;
        }

        private static String colour(Random random) {
            return String.format("#%06x", random.nextInt(1 << 24));
        }
    }

    /** Just enough JSON: objects keep their order and numbers keep their text, so a scene goes back out as it came. */
    static final class Json {
        /** A number as written. */
        record Num(String text) {
            @Override
            public String toString() {
                return text;
            }
        }

        private final String text;
        private int at;

        private Json(String text) {
            this.text = text;
        }

        static Object parse(String text) {
            Json json = new Json(text);
            Object value = json.value();
            json.space();
            if (json.at != text.length()) {
                throw json.error("trailing text");
            }
            return value;
        }

        @SuppressWarnings("unchecked")
        static Map<String, Object> object(Object value) {
            if (!(value instanceof Map)) {
                throw new IllegalArgumentException("not a JSON object: " + value);
            }
            return (Map<String, Object>) value;
        }

        @SuppressWarnings("unchecked")
        static List<Object> list(Object value) {
            if (!(value instanceof List)) {
                throw new IllegalArgumentException("not a JSON array: " + value);
            }
            return (List<Object>) value;
        }

        static long number(Map<String, Object> object, String key) {
            Object value = object.get(key);
            if (!(value instanceof Num n)) {
                throw new IllegalArgumentException("expected a number at " + key + ", got " + value);
            }
            return Long.parseLong(n.text());
        }

        static double[] vector(Object value) {
            List<Object> list = list(value);
            double[] v = new double[list.size()];
            for (int i = 0; i < v.length; i++) {
                v[i] = Double.parseDouble(list.get(i).toString());
            }
            return v;
        }

        static String write(Object value) {
            StringBuilder out = new StringBuilder();
            write(value, out);
            return out.toString();
        }

        private static void write(Object value, StringBuilder out) {
            if (value instanceof Map<?, ?> map) {
                out.append('{');
                String comma = "";
                for (Map.Entry<?, ?> entry : map.entrySet()) {
                    out.append(comma);
                    writeString(entry.getKey().toString(), out);
                    out.append(':');
                    write(entry.getValue(), out);
                    comma = ",";
                }
                out.append('}');
            } else if (value instanceof List<?> list) {
                out.append('[');
                for (int i = 0; i < list.size(); i++) {
                    out.append(i > 0 ? "," : "");
                    write(list.get(i), out);
                }
                out.append(']');
            } else if (value instanceof String s) {
                writeString(s, out);
            } else {
                out.append(value); // Num, Integer, Double, Boolean, null
            }
        }

        private static void writeString(String s, StringBuilder out) {
            out.append('"');
            for (int i = 0; i < s.length(); i++) {
                char c = s.charAt(i);
                switch (c) {
                    case '"' -> out.append("\\\"");
                    case '\\' -> out.append("\\\\");
                    case '\n' -> out.append("\\n");
                    case '\r' -> out.append("\\r");
                    case '\t' -> out.append("\\t");
                    default -> {
                        if (c < 0x20) {
                            out.append(String.format("\\u%04x", (int) c));
                        } else {
                            out.append(c);
                        }
                    }
                }
            }
            out.append('"');
        }

        private Object value() {
            space();
            if (at >= text.length()) {
                throw error("unexpected end");
            }
            char c = text.charAt(at);
            if (c == '{') {
                Map<String, Object> map = new LinkedHashMap<>();
                at++;
                space();
                if (peek('}')) {
                    return map;
                }
                do {
                    space();
                    String key = stringLiteral();
                    space();
                    expect(':');
                    map.put(key, value());
                    space();
                } while (peek(','));
                expect('}');
                return map;
            }
            if (c == '[') {
                List<Object> list = new ArrayList<>();
                at++;
                space();
                if (peek(']')) {
                    return list;
                }
                do {
                    list.add(value());
                    space();
                } while (peek(','));
                expect(']');
                return list;
            }
            if (c == '"') {
                return stringLiteral();
            }
            for (String word : new String[] {"true", "false", "null"}) {
                if (text.startsWith(word, at)) {
                    at += word.length();
                    return word.equals("null") ? null : Boolean.valueOf(word);
                }
            }
            int start = at;
            while (at < text.length() && "+-0123456789.eE".indexOf(text.charAt(at)) >= 0) {
                at++;
            }
            if (start == at) {
                throw error("unexpected '" + c + "'");
            }
            return new Num(text.substring(start, at));
        }

        private String stringLiteral() {
            expect('"');
            StringBuilder out = new StringBuilder();
            while (true) {
                if (at >= text.length()) {
                    throw error("unterminated string");
                }
                char c = text.charAt(at++);
                if (c == '"') {
                    return out.toString();
                }
                if (c != '\\') {
                    out.append(c);
                    continue;
                }
                char e = text.charAt(at++);
                switch (e) {
                    case 'n' -> out.append('\n');
                    case 't' -> out.append('\t');
                    case 'r' -> out.append('\r');
                    case 'b' -> out.append('\b');
                    case 'f' -> out.append('\f');
                    case 'u' -> {
                        out.append((char) Integer.parseInt(text.substring(at, at + 4), 16));
                        at += 4;
                    }
                    default -> out.append(e);
                }
            }
        }

        private void space() {
            while (at < text.length() && Character.isWhitespace(text.charAt(at))) {
                at++;
            }
        }

        private boolean peek(char c) {
            if (at < text.length() && text.charAt(at) == c) {
                at++;
                return true;
            }
            return false;
        }

        private void expect(char c) {
            if (!peek(c)) {
                throw error("expected '" + c + "'");
            }
        }

        private IllegalArgumentException error(String message) {
            return new IllegalArgumentException("JSON at " + at + ": " + message);
        }
    }
}

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

/**
 * A load test of a running Ray Studio server on loopback: N clients for T seconds send a mix of
 * small synchronous renders, render jobs (polled, cancelled, or watched over server-sent events)
 * and invalid scenes; then, one at a time, a few jobs with a 58,000-triangle inline mesh, so that
 * finished jobs (the server keeps the last 50) that hold on to their scene show in the heap. It
 * checks the answers, the jobs, health, heap and threads, prints a report and exits 1 if any check
 * failed (2 for bad arguments).
 *
 * <pre>
 * java scripts/LoadTest.java --url http://127.0.0.1:8080 [--clients 50] [--seconds 60]
 *      [--pid PID] [--scenes scenes] [--drain-seconds 60] [--idle-seconds 10]
 *      [--heap-margin-mib 64] [--retry-cap-ms 2000] [--warmup-seconds 5] [--mesh-jobs 20] [--seed 1]
 *      [--keys KEY1,KEY2,...] [--greedy 0] [--principal-limit-check true]
 * </pre>
 *
 * With sign-in on, --keys: client i sends {@code Authorization: Bearer} with key i mod n on every
 * request; the health, metrics, final-state and mesh-job reads use the first key. --greedy N adds N
 * clients with the first key that only submit jobs, as fast as Retry-After lets them, and never
 * cancel; the report then shows, per principal, the jobs accepted, the 429s and what they named (the
 * per-principal limit, the server's queue, ...), and the polite clients' latencies and answer rates.
 * With both, two more checks: the greedy principal's 429s name the per-principal limit (skipped with
 * --principal-limit-check false, for a run with the limit raised out of reach) and every other
 * principal had jobs accepted.
 *
 * The server must expose the metrics endpoint (MANAGEMENT_ENDPOINTS_WEB_EXPOSURE_INCLUDE=health,info,metrics).
 * With --pid, heap is read after {@code jcmd PID GC.run}; without, as the least of a few reads.
 * No dependencies: JDK 17's source launcher and java.net.http.
 */
public final class LoadTest {

    /** Actions and their weights out of 100. */
    enum Action { RENDER, JOB, EVENTS, CANCEL, INVALID }

    static final int[] WEIGHTS = {45, 20, 15, 10, 10};
    static final int[][] SIZES = {{32, 24}, {64, 48}, {96, 72}, {128, 96}, {160, 120}};
    static final int[] SAMPLES = {1, 2, 4, 8, 16};
    static final List<String> SCENES = List.of("minimal", "three-spheres", "six-materials", "coloured-lights",
            "still-life", "mirror-room", "glass-pattern", "mesh");
    /** Each one is a 400 at either endpoint, before anything renders. */
    static final List<String> INVALID = List.of(
            "{\"objects\": [{\"type\": \"sphere\", \"radius\": -1}]}",
            "{\"image\": {\"width\": 0, \"height\": 48}, \"objects\": []}",
            "{\"objects\": [], \"colour\": \"#ffffff\"}",
            "{\"objects\": [{\"type\": \"sphere\"",
            "{\"render\": {\"samples\": 0}, \"objects\": []}",
            "{\"camera\": {\"up\": [0, 0, 0]}, \"objects\": []}",
            "{\"objects\": [{\"type\": \"teapot\"}]}",
            "");
    static final long POLL_MILLIS = 100;
    /** The mesh jobs' inline mesh: 2 x 170 x 170 triangles, 2.4 MB of OBJ. */
    static final int MESH_GRID = 170;

    /**
     * @param warmupSeconds requests started in the first seconds are counted and checked but not timed
     * @param meshJobs      mesh jobs after the load, one at a time
     * @param keys          API keys (empty with sign-in off); client i uses key i mod n
     * @param greedy        extra clients with the first key that only submit jobs
     * @param principalLimitCheck with keys and greedy clients, check that the greedy principal's 429s name its limit
     */
    record Options(URI url, int clients, int seconds, long pid, Path scenes, int drainSeconds, int idleSeconds,
                   long heapMarginMiB, long retryCapMillis, int warmupSeconds, int meshJobs, long seed,
                   List<String> keys, int greedy, boolean principalLimitCheck) {

        static Options parse(String[] args) {
            Map<String, String> given = new LinkedHashMap<>();
            for (int i = 0; i < args.length; i += 2) {
                if (!args[i].startsWith("--") || i + 1 >= args.length) {
                    throw new IllegalArgumentException("expected --name value pairs, got " + String.join(" ", args));
                }
                given.put(args[i].substring(2), args[i + 1]);
            }
            Options options = new Options(URI.create(take(given, "url", "http://127.0.0.1:8080")),
                    Integer.parseInt(take(given, "clients", "50")), Integer.parseInt(take(given, "seconds", "60")),
                    Long.parseLong(take(given, "pid", "0")), Path.of(take(given, "scenes", "scenes")),
                    Integer.parseInt(take(given, "drain-seconds", "60")),
                    Integer.parseInt(take(given, "idle-seconds", "10")),
                    Long.parseLong(take(given, "heap-margin-mib", "64")),
                    Long.parseLong(take(given, "retry-cap-ms", "2000")),
                    Integer.parseInt(take(given, "warmup-seconds", "5")),
                    Integer.parseInt(take(given, "mesh-jobs", "20")), Long.parseLong(take(given, "seed", "1")),
                    Arrays.stream(take(given, "keys", "").split(",")).map(String::trim).filter(k -> !k.isEmpty())
                            .toList(),
                    Integer.parseInt(take(given, "greedy", "0")),
                    Boolean.parseBoolean(take(given, "principal-limit-check", "true")));
            if (!given.isEmpty()) {
                throw new IllegalArgumentException("unknown options: " + given.keySet());
            }
            return options;
        }

        private static String take(Map<String, String> given, String name, String fallback) {
            String value = given.remove(name);
            return value != null ? value : fallback;
        }
    }

    public static void main(String[] args) throws Exception {
        Options options;
        List<Map<String, Object>> scenes = new ArrayList<>();
        try {
            options = Options.parse(args);
            for (String name : SCENES) {
                scenes.add(Json.object(Json.parse(Files.readString(options.scenes().resolve(name + ".json")))));
            }
        } catch (IllegalArgumentException | IOException e) {
            System.err.println("error: " + e.getMessage());
            System.exit(2);
            return;
        }
        System.exit(new LoadTest(options, scenes).run() ? 0 : 1);
    }

    private final Options options;
    private final List<Map<String, Object>> scenes;
    private final Map<String, Object> meshScene = meshScene(MESH_GRID);
    private final HttpClient http = HttpClient.newBuilder().version(HttpClient.Version.HTTP_1_1)
            .connectTimeout(Duration.ofSeconds(5)).build();
    private final Map<String, Latencies> latencies = new ConcurrentHashMap<>();
    /** Every accepted job id and its final state, or "" until a client has seen it final. */
    private final Map<String, String> jobs = new ConcurrentHashMap<>();
    private final Problems problems = new Problems();
    private final AtomicLong retryWaits = new AtomicLong();
    private final AtomicLong gaveUp = new AtomicLong();
    /** The key index of each accepted job's client: only its principal may read it. */
    private final Map<String, Integer> jobKeys = new ConcurrentHashMap<>();
    /**
     * The greedy clients' jobs not yet seen final: they never poll them, so the monitor does, every
     * second, before the server drops them (it keeps only the last 50 finished jobs).
     */
    private final java.util.Set<String> greedyJobs = ConcurrentHashMap.newKeySet();
    /** The report's rows per principal: the polite clients of each key, then the greedy clients. */
    private final List<Group> groups = new ArrayList<>();
    private Group greedyGroup;
    /** Who the current thread sends as; the main and monitor threads send as the first key, in no group. */
    private final ThreadLocal<Caller> caller = ThreadLocal.withInitial(() -> new Caller(0, null));
    private volatile long timedFrom = Long.MAX_VALUE, stopAt, drainUntil;

    LoadTest(Options options, List<Map<String, Object>> scenes) {
        this.options = options;
        this.scenes = scenes;
    }

    /** Runs the whole test; true when every check passed. */
    boolean run() throws Exception {
        awaitHealthy(Duration.ofSeconds(60));
        int keys = Math.max(1, options.keys().size());
        for (int k = 0; k < keys; k++) {
            groups.add(new Group(principal(k), k, false));
        }
        for (int i = 0; i < options.clients(); i++) {
            groups.get(i % keys).clients++;
        }
        if (options.greedy() > 0) {
            greedyGroup = new Group(groups.get(0).name + " (greedy)", 0, true);
            greedyGroup.clients = options.greedy();
            groups.add(greedyGroup);
        }
        Memory before = memory();
        System.out.printf(Locale.ROOT, "before: heap %.1f MiB, %d threads; %d clients%s for %d s%s%n",
                mib(before.heap), before.threads, options.clients(),
                options.greedy() > 0 ? " + " + options.greedy() + " greedy" : "", options.seconds(),
                options.keys().isEmpty() ? "" : "; principals " + groups.stream().filter(g -> !g.greedy)
                        .map(g -> g.name).toList());

        long start = System.nanoTime();
        timedFrom = start + TimeUnit.SECONDS.toNanos(options.warmupSeconds());
        stopAt = start + TimeUnit.SECONDS.toNanos(options.seconds());
        drainUntil = stopAt + TimeUnit.SECONDS.toNanos(options.drainSeconds());
        ScheduledExecutorService monitor = Executors.newSingleThreadScheduledExecutor();
        monitor.scheduleWithFixedDelay(() -> {
            checkHealth();
            sweepGreedyJobs();
        }, 0, 1, TimeUnit.SECONDS);
        List<Thread> clients = new ArrayList<>();
        for (int i = 0; i < options.clients(); i++) {
            Random random = new Random(options.seed() * 1_000_003 + i);
            Caller as = new Caller(i % keys, groups.get(i % keys));
            Thread client = new Thread(() -> {
                caller.set(as);
                client(random);
            }, "client-" + i);
            client.start();
            clients.add(client);
        }
        for (int i = 0; i < options.greedy(); i++) {
            Random random = new Random(options.seed() * 2_000_003 + i);
            Caller as = new Caller(0, greedyGroup);
            Thread client = new Thread(() -> {
                caller.set(as);
                greedyClient(random);
            }, "greedy-" + i);
            client.start();
            clients.add(client);
        }
        for (Thread client : clients) {
            client.join(Math.max(1, TimeUnit.NANOSECONDS.toMillis(drainUntil - System.nanoTime()) + 30_000));
            if (client.isAlive()) {
                problems.add(client.getName() + " still busy 30 s after the drain timeout");
            }
        }
        long loadNanos = System.nanoTime() - start;
        monitor.shutdown();
        monitor.awaitTermination(15, TimeUnit.SECONDS);
        checkJobsFinal();
        checkPrincipals();
        checkHealth();
        meshJobs();

        Thread.sleep(TimeUnit.SECONDS.toMillis(options.idleSeconds()));
        Memory after = memory();
        checkHealth();
        long margin = options.heapMarginMiB() << 20;
        if (after.heap > before.heap + margin) {
            problems.add(String.format(Locale.ROOT, "heap after %.1f MiB is more than start %.1f MiB + %d MiB",
                    mib(after.heap), mib(before.heap), options.heapMarginMiB()));
        }
        // the server needs at most one request thread per connection; per-render pools that leak add many more
        int threadCeiling = before.threads + options.clients() + options.greedy() + 16;
        if (after.threads > threadCeiling) {
            problems.add("threads after " + after.threads + " > start " + before.threads + " + clients "
                    + (options.clients() + options.greedy()) + " + 16");
        }
        report(loadNanos, before, after, margin, threadCeiling);
        return problems.isEmpty();
    }

    // ---- clients

    private void client(Random random) {
        while (System.nanoTime() < stopAt) {
            int roll = random.nextInt(100);
            int i = 0;
            while (roll >= WEIGHTS[i]) {
                roll -= WEIGHTS[i++];
            }
            try {
                switch (Action.values()[i]) {
                    case RENDER -> render(random);
                    case JOB -> job(random, false);
                    case EVENTS -> job(random, true);
                    case CANCEL -> cancel(random);
                    case INVALID -> invalid(random);
                }
            } catch (IOException | RuntimeException e) {
                problems.add(Thread.currentThread().getName() + ": " + e);
            } catch (InterruptedException e) {
                return;
            }
        }
    }

    /** Only submits jobs, one after another, waiting only as a 429's or 503's Retry-After says; never cancels. */
    private void greedyClient(Random random) {
        while (System.nanoTime() < stopAt) {
            try {
                submit(variant(pick(random), random, random.nextInt(SIZES.length),
                        SAMPLES[random.nextInt(SAMPLES.length)]));
            } catch (IOException | RuntimeException e) {
                problems.add(Thread.currentThread().getName() + ": " + e);
            } catch (InterruptedException e) {
                return;
            }
        }
    }

    private void render(Random random) throws IOException, InterruptedException {
        Variant variant = variant(pick(random), random, random.nextInt(SIZES.length),
                SAMPLES[random.nextInt(SAMPLES.length)]);
        HttpResponse<byte[]> response = sendRetrying("render", post("/api/render", variant.json));
        if (response != null && expect("render", response, 200)) {
            checkImage("render", response, variant);
            String size = response.headers().firstValue("X-Image-Size").orElse("");
            if (!size.equals(variant.width + "x" + variant.height)) {
                problems.add("render: X-Image-Size " + size + " for a " + variant.width + "x" + variant.height
                        + " scene");
            }
        }
    }

    /** Submits a job, then polls it (or reads its event stream) to the end, then fetches a done job's image. */
    private void job(Random random, boolean events) throws IOException, InterruptedException {
        Variant variant = variant(pick(random), random, random.nextInt(SIZES.length),
                SAMPLES[random.nextInt(SAMPLES.length)]);
        String id = submit(variant);
        if (id == null) {
            return;
        }
        String state = events ? watchEvents(id) : pollToEnd(id);
        finish(id, state, variant);
    }

    /**
     * Submits the largest job of the mix, waits a moment, cancels it and follows it to the end, by
     * polling or on its event stream.
     */
    private void cancel(Random random) throws IOException, InterruptedException {
        Variant variant = variant(pick(random), random, SIZES.length - 1, 16);
        String id = submit(variant);
        if (id == null) {
            return;
        }
        Thread.sleep(random.nextInt(150));
        HttpResponse<byte[]> response = send("job-cancel", request("/api/jobs/" + id).DELETE());
        if (expect("job-cancel", response, 202)) {
            String state = Json.string(Json.object(Json.parse(body(response))), "state");
            if (!List.of("queued", "running", "done", "cancelled").contains(state)) {
                problems.add("job-cancel: job " + id + " answered state " + state);
            }
        }
        String state = random.nextBoolean() ? pollToEnd(id) : watchEvents(id);
        if ("failed".equals(state)) {
            problems.add("job " + id + " failed after a cancel");
        }
        finish(id, state, variant);
    }

    private void invalid(Random random) throws IOException, InterruptedException {
        String body = INVALID.get(random.nextInt(INVALID.size()));
        String path = random.nextBoolean() ? "/api/render" : "/api/jobs";
        HttpResponse<byte[]> response = send("invalid", post(path, body));
        if (expect("invalid", response, 400)) {
            String type = response.headers().firstValue("Content-Type").orElse("");
            if (!type.startsWith("application/problem+json") || !body(response).contains("\"status\":400")) {
                problems.add("invalid: 400 from " + path + " without a problem body (" + type + ")");
            }
        }
    }

    /** The job's id once accepted, or null when the load ended before the queue took it. */
    private String submit(Variant variant) throws IOException, InterruptedException {
        long begin = System.nanoTime();
        HttpResponse<byte[]> response = sendRetrying("job-submit", post("/api/jobs", variant.json));
        if (response == null || !expect("job-submit", response, 202)) {
            return null;
        }
        String id = Json.string(Json.object(Json.parse(body(response))), "id");
        jobKeys.put(id, caller.get().keyIndex());
        jobs.put(id, "");
        Group group = caller.get().group();
        if (group != null) {
            group.accepted.incrementAndGet();
            group.acceptWait.add(System.nanoTime() - begin, begin >= timedFrom);
            if (group.greedy) {
                greedyJobs.add(id);
            }
        }
        String location = response.headers().firstValue("Location").orElse("");
        if (!location.endsWith("/api/jobs/" + id)) {
            problems.add("job-submit: Location '" + location + "' for job " + id);
        }
        return id;
    }

    /** The final state, or null if the job was not final by the drain timeout (or could not be read). */
    private String pollToEnd(String id) throws IOException, InterruptedException {
        return pollToEnd(id, "job-status");
    }

    private String pollToEnd(String id, String kind) throws IOException, InterruptedException {
        while (System.nanoTime() < drainUntil) {
            HttpResponse<byte[]> response = send(kind, request("/api/jobs/" + id).GET());
            if (!expect(kind, response, 200)) {
                return null;
            }
            String state = Json.string(Json.object(Json.parse(body(response))), "state");
            if (isFinal(state)) {
                return state;
            }
            Thread.sleep(POLL_MILLIS);
        }
        return null;
    }

    /**
     * Reads a job's event stream to its end: a status first, tiles, one end event, then the server
     * closes it. A watchdog closes the stream at the drain timeout.
     */
    private String watchEvents(String id) throws IOException, InterruptedException {
        long begin = System.nanoTime();
        HttpResponse<InputStream> response = http.send(request("/api/jobs/" + id + "/events")
                .header("Accept", "text/event-stream").timeout(Duration.ofSeconds(30)).GET().build(),
                HttpResponse.BodyHandlers.ofInputStream());
        if (response.statusCode() != 200) {
            byte[] bytes = response.body().readAllBytes();
            record("job-events", response.statusCode(), begin);
            problems.add("job-events: " + response.statusCode() + " for job " + id + ": "
                    + new String(bytes, StandardCharsets.UTF_8));
            return null;
        }
        Thread watchdog = Watchdog.start(response.body(), drainUntil);
        List<String> names = new ArrayList<>();
        String endData = null;
        try (BufferedReader reader = new BufferedReader(new InputStreamReader(response.body(), StandardCharsets.UTF_8))) {
            String name = null;
            StringBuilder data = new StringBuilder();
            for (String line; (line = reader.readLine()) != null; ) {
                if (line.startsWith("event:")) {
                    name = line.substring(6).trim();
                } else if (line.startsWith("data:")) {
                    data.append(line.substring(5));
                } else if (line.isEmpty() && name != null) {
                    names.add(name);
                    if (name.equals("end")) {
                        endData = data.toString();
                    }
                    name = null;
                    data.setLength(0);
                }
            }
        } catch (IOException e) {
            names.add("(" + e.getClass().getSimpleName() + ")");
        } finally {
            watchdog.interrupt();
        }
        record("job-events", 200, begin);
        boolean ordered = !names.isEmpty() && names.get(0).equals("status") && endData != null
                && names.indexOf("end") == names.size() - 1;
        if (!ordered) {
            problems.add("job-events: job " + id + " streamed " + summary(names));
            return null;
        }
        return Json.string(Json.object(Json.parse(endData)), "state");
    }

    /** Records the job's final state (or that it has none yet) and fetches a done job's image. */
    private void finish(String id, String state, Variant variant) throws IOException, InterruptedException {
        if (state == null) {
            return; // checkJobsFinal asks again
        }
        jobs.put(id, state);
        if (state.equals("done")) {
            HttpResponse<byte[]> image = send("job-image", request("/api/jobs/" + id + "/image").GET());
            if (expect("job-image", image, 200)) {
                checkImage("job-image", image, variant);
            }
        } else if (state.equals("failed")) {
            problems.add("job " + id + " failed");
        }
    }

    // ---- HTTP

    private HttpRequest.Builder post(String path, String json) {
        return request(path).header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString(json));
    }

    private URI uri(String path) {
        return options.url().resolve(path);
    }

    /** A request to path, signed with the current thread's key (none without --keys). */
    private HttpRequest.Builder request(String path) {
        return request(path, caller.get().keyIndex());
    }

    private HttpRequest.Builder request(String path, int keyIndex) {
        HttpRequest.Builder builder = HttpRequest.newBuilder(uri(path));
        if (!options.keys().isEmpty()) {
            builder.header("Authorization", "Bearer " + options.keys().get(keyIndex % options.keys().size()));
        }
        return builder;
    }

    /** The principal a key signs in as (GET /api/me), or "key N" if it does not answer; "(no key)" without keys. */
    private String principal(int keyIndex) throws IOException, InterruptedException {
        if (options.keys().isEmpty()) {
            return "(no key)";
        }
        HttpResponse<String> response = http.send(request("/api/me", keyIndex).GET().build(),
                HttpResponse.BodyHandlers.ofString());
        String name = response.statusCode() == 200 ? Json.string(Json.object(Json.parse(response.body())), "principal")
                : null;
        if (name == null || name.isEmpty()) {
            problems.add("/api/me: " + response.statusCode() + " for key " + (keyIndex + 1) + ": "
                    + abbreviate(response.body()));
            return "key " + (keyIndex + 1);
        }
        return name;
    }

    private HttpResponse<byte[]> send(String kind, HttpRequest.Builder request) throws IOException, InterruptedException {
        long begin = System.nanoTime();
        HttpResponse<byte[]> response = http.send(request.timeout(Duration.ofSeconds(60)).build(),
                HttpResponse.BodyHandlers.ofByteArray());
        record(kind, response.statusCode(), begin);
        return response;
    }

    /**
     * Sends, and while the answer is 429 or 503 waits as its Retry-After says (at most the cap) and
     * sends again; null if the load ended first.
     */
    private HttpResponse<byte[]> sendRetrying(String kind, HttpRequest.Builder request)
            throws IOException, InterruptedException {
        while (true) {
            HttpResponse<byte[]> response = send(kind, request);
            int status = response.statusCode();
            if (status != 429 && status != 503) {
                return response;
            }
            Group group = caller.get().group();
            if (group != null) {
                group.refusals.computeIfAbsent(kind + " " + status + " " + named(response), k -> new AtomicLong())
                        .incrementAndGet();
            }
            long wait = retryAfterMillis(kind, response);
            long left = TimeUnit.NANOSECONDS.toMillis(stopAt - System.nanoTime());
            if (wait >= left) {
                gaveUp.incrementAndGet(); // waits out the load rather than starting something new
                if (group != null) {
                    group.gaveUp.incrementAndGet();
                }
                Thread.sleep(Math.max(0, left));
                return null;
            }
            retryWaits.incrementAndGet();
            Thread.sleep(wait);
        }
    }

    /** What a 429 or 503 names as full: the principal's own jobs, the server's queue, its render memory, ... */
    static String named(HttpResponse<byte[]> response) {
        String text = body(response);
        if (text.contains("max-jobs-per-principal")) {
            return "principal-limit";
        }
        if (text.contains("render queue is full")) {
            return "queue";
        }
        if (text.contains("render memory")) {
            return "memory";
        }
        if (text.contains("shutting down")) {
            return "shutdown";
        }
        return "other";
    }

    /** The wait a 429 or 503 asks for, capped, with a little jitter; a missing header is a problem. */
    private long retryAfterMillis(String kind, HttpResponse<?> response) {
        String header = response.headers().firstValue("Retry-After").orElse(null);
        long seconds;
        try {
            seconds = Long.parseLong(header == null ? "" : header.trim());
        } catch (NumberFormatException e) {
            problems.add(kind + ": " + response.statusCode() + " with Retry-After '" + header + "'");
            seconds = 1;
        }
        long jitter = (long) (Math.random() * 100);
        return Math.min(seconds * 1000, options.retryCapMillis()) + jitter;
    }

    /** True if the status is the one wanted; a 429 or 503 with Retry-After is fine anywhere, anything else a problem. */
    private boolean expect(String kind, HttpResponse<byte[]> response, int wanted) {
        int status = response.statusCode();
        if (status == wanted) {
            return true;
        }
        if ((status == 429 || status == 503) && response.headers().firstValue("Retry-After").isPresent()) {
            return false;
        }
        problems.add(kind + ": " + status + " " + response.uri().getPath() + ": " + abbreviate(body(response)));
        return false;
    }

    private void checkImage(String kind, HttpResponse<byte[]> response, Variant variant) {
        byte[] bytes = response.body();
        String type = response.headers().firstValue("Content-Type").orElse("");
        boolean png = bytes.length > 8 && (bytes[0] & 0xff) == 0x89 && bytes[1] == 'P' && bytes[2] == 'N';
        boolean jpeg = bytes.length > 4 && (bytes[0] & 0xff) == 0xff && (bytes[1] & 0xff) == 0xd8;
        boolean ok = variant.format.equals("png") ? png && type.equals("image/png") : jpeg && type.equals("image/jpeg");
        if (!ok) {
            problems.add(kind + ": wanted " + variant.format + ", got " + type + " (" + bytes.length + " bytes)");
        }
    }

    private void record(String kind, int status, long beginNanos) {
        long nanos = System.nanoTime() - beginNanos;
        latencies.computeIfAbsent(kind + " " + status, k -> new Latencies()).add(nanos, beginNanos >= timedFrom);
        Group group = caller.get().group();
        if (group != null) {
            group.latencies.computeIfAbsent(kind + " " + status, k -> new Latencies()).add(nanos, beginNanos >= timedFrom);
        }
    }

    private void checkHealth() {
        try {
            long begin = System.nanoTime();
            HttpResponse<String> response = http.send(request("/actuator/health")
                    .timeout(Duration.ofSeconds(10)).GET().build(), HttpResponse.BodyHandlers.ofString());
            record("health", response.statusCode(), begin);
            if (response.statusCode() != 200 || !response.body().contains("\"status\":\"UP\"")) {
                problems.add("health: " + response.statusCode() + " " + abbreviate(response.body()));
            }
        } catch (IOException e) {
            problems.add("health: " + e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Reads each greedy job not yet seen final (with the first key, the greedy principal's) and records the final ones. */
    private void sweepGreedyJobs() {
        for (String id : greedyJobs) {
            try {
                long begin = System.nanoTime();
                HttpResponse<byte[]> response = http.send(request("/api/jobs/" + id).timeout(Duration.ofSeconds(10))
                        .GET().build(), HttpResponse.BodyHandlers.ofByteArray());
                record("greedy-status", response.statusCode(), begin);
                if (expect("greedy-status", response, 200)) {
                    String state = Json.string(Json.object(Json.parse(body(response))), "state");
                    if (isFinal(state)) {
                        jobs.put(id, state);
                        greedyJobs.remove(id);
                        if (state.equals("failed")) {
                            problems.add("job " + id + " failed");
                        }
                    }
                }
            } catch (IOException | RuntimeException e) {
                problems.add("greedy-status: " + e);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    private void awaitHealthy(Duration timeout) throws InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        while (true) {
            try {
                HttpResponse<String> response = http.send(request("/actuator/health").GET().build(),
                        HttpResponse.BodyHandlers.ofString());
                if (response.body().contains("\"status\":\"UP\"")) {
                    return;
                }
            } catch (IOException e) {
                // not listening yet
            }
            if (System.nanoTime() > deadline) {
                throw new IllegalStateException("the server at " + options.url() + " did not become healthy");
            }
            Thread.sleep(250);
        }
    }

    // ---- jobs and memory

    /**
     * Mesh jobs, one at a time, each to done and its image: the server keeps the last 50 finished
     * jobs, so if a finished job held its scene these would hold about 7 MB each.
     */
    private void meshJobs() throws IOException, InterruptedException {
        Random random = new Random(options.seed());
        stopAt = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        drainUntil = stopAt;
        for (int i = 0; i < options.meshJobs(); i++) {
            Variant variant = variant(meshScene, random, 0, 1);
            HttpResponse<byte[]> response = sendRetrying("mesh-submit", post("/api/jobs", variant.json));
            if (response == null || !expect("mesh-submit", response, 202)) {
                problems.add("mesh job " + i + " was not accepted within 60 s");
                return;
            }
            String id = Json.string(Json.object(Json.parse(body(response))), "id");
            String state = pollToEnd(id, "mesh-status");
            if (!"done".equals(state)) {
                problems.add("mesh job " + id + " ended " + state);
                continue;
            }
            HttpResponse<byte[]> image = send("mesh-image", request("/api/jobs/" + id + "/image").GET());
            if (expect("mesh-image", image, 200)) {
                checkImage("mesh-image", image, variant);
            }
        }
    }

    private static boolean isFinal(String state) {
        return "done".equals(state) || "failed".equals(state) || "cancelled".equals(state);
    }

    /**
     * Every accepted job must have been seen final by its client, or be final by the drain timeout (a
     * greedy client's jobs are never polled by it), read with its principal's key.
     */
    private void checkJobsFinal() throws InterruptedException {
        for (Map.Entry<String, String> job : jobs.entrySet()) {
            if (isFinal(job.getValue())) {
                continue;
            }
            String state = "unreadable";
            while (true) {
                try {
                    HttpResponse<String> response = http.send(request("/api/jobs/" + job.getKey(),
                            jobKeys.getOrDefault(job.getKey(), 0)).GET().build(), HttpResponse.BodyHandlers.ofString());
                    state = response.statusCode() == 200
                            ? Json.string(Json.object(Json.parse(response.body())), "state")
                            : "HTTP " + response.statusCode();
                } catch (IOException e) {
                    state = e.toString();
                }
                if (isFinal(state) || System.nanoTime() >= drainUntil) {
                    break;
                }
                Thread.sleep(POLL_MILLIS);
            }
            if (isFinal(state)) {
                job.setValue(state);
            } else {
                problems.add("lost job " + job.getKey() + ": " + state + " " + options.drainSeconds()
                        + " s after the load stopped");
            }
        }
    }

    /**
     * With keys and greedy clients: the greedy principal was held to its own limit (its 429s name it),
     * and every other principal still had jobs accepted.
     */
    private void checkPrincipals() {
        if (options.keys().isEmpty() || greedyGroup == null) {
            return;
        }
        if (options.principalLimitCheck()) {
            long limit = 0;
            for (Map.Entry<String, AtomicLong> refusal : greedyGroup.refusals.entrySet()) {
                limit += refusal.getKey().endsWith(" principal-limit") ? refusal.getValue().get() : 0;
            }
            if (limit == 0) {
                problems.add("the greedy principal " + groups.get(0).name + " got no 429 naming the per-principal limit: "
                        + new TreeMap<>(greedyGroup.refusals));
            }
        }
        for (Group group : groups) {
            if (group.keyIndex > 0 && group.clients > 0 && group.accepted.get() == 0) {
                problems.add("principal " + group.name + " had no job accepted beside the greedy principal");
            }
        }
    }

    record Memory(long heap, int threads) {
    }

    /** Heap after a full GC (with --pid) as the least of three reads, and the live threads. */
    private Memory memory() throws IOException, InterruptedException {
        if (options.pid() > 0) {
            Path jcmd = Path.of(System.getProperty("java.home"), "bin", "jcmd");
            Process gc = new ProcessBuilder(jcmd.toString(), Long.toString(options.pid()), "GC.run")
                    .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
            if (!gc.waitFor(30, TimeUnit.SECONDS) || gc.exitValue() != 0) {
                System.out.println("note: jcmd GC.run failed; heap is the least of the reads");
            }
        }
        long heap = Long.MAX_VALUE;
        for (int i = 0; i < 3; i++) {
            Thread.sleep(500);
            heap = Math.min(heap, (long) metric("jvm.memory.used?tag=area:heap"));
        }
        return new Memory(heap, (int) metric("jvm.threads.live"));
    }

    private double metric(String query) throws IOException, InterruptedException {
        HttpResponse<String> response = http.send(request("/actuator/metrics/" + query).GET().build(),
                HttpResponse.BodyHandlers.ofString());
        if (response.statusCode() != 200) {
            throw new IllegalStateException("metrics: " + response.statusCode() + " for " + query
                    + " (start the server with MANAGEMENT_ENDPOINTS_WEB_EXPOSURE_INCLUDE=health,info,metrics)");
        }
        Object measurements = Json.object(Json.parse(response.body())).get("measurements");
        return Double.parseDouble(Json.object(((List<?>) measurements).get(0)).get("value").toString());
    }

    // ---- scenes

    /** A scene of the mix at a size, sample count and format. */
    record Variant(String json, int width, int height, String format) {
    }

    private Map<String, Object> pick(Random random) {
        return scenes.get(random.nextInt(scenes.size()));
    }

    /** A flat grid of n x n squares, two triangles each, standing 2 m wide on the floor, as inline OBJ. */
    static Map<String, Object> meshScene(int n) {
        StringBuilder obj = new StringBuilder();
        for (int j = 0; j <= n; j++) {
            for (int i = 0; i <= n; i++) {
                obj.append("v ").append(2.0 * i / n - 1).append(' ').append(2.0 * j / n).append(" 0\n");
            }
        }
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 1, d = c + 1;
                obj.append("f ").append(a).append(' ').append(b).append(' ').append(d).append('\n');
                obj.append("f ").append(a).append(' ').append(d).append(' ').append(c).append('\n');
            }
        }
        Map<String, Object> mesh = new LinkedHashMap<>();
        mesh.put("type", "mesh");
        mesh.put("obj", obj.toString());
        mesh.put("rotation", List.of(0, 30, 0));
        Map<String, Object> plane = new LinkedHashMap<>();
        plane.put("type", "plane");
        Map<String, Object> scene = new LinkedHashMap<>();
        scene.put("name", "load-test-grid");
        scene.put("objects", List.of(mesh, plane));
        return scene;
    }

    private Variant variant(Map<String, Object> original, Random random, int size, int samples) {
        Map<String, Object> scene = new LinkedHashMap<>(original);
        String format = random.nextBoolean() ? "png" : "jpg";
        Map<String, Object> image = new LinkedHashMap<>(Json.object(scene.getOrDefault("image", Map.of())));
        image.put("width", SIZES[size][0]);
        image.put("height", SIZES[size][1]);
        image.put("format", format);
        scene.put("image", image);
        Map<String, Object> render = new LinkedHashMap<>(Json.object(scene.getOrDefault("render", Map.of())));
        render.put("samples", samples);
        scene.put("render", render);
        return new Variant(Json.write(scene), SIZES[size][0], SIZES[size][1], format);
    }

    // ---- report

    private void report(long loadNanos, Memory before, Memory after, long margin, int threadCeiling) {
        double seconds = loadNanos / 1e9;
        long requests = 0, renders = 0, busy = 0, full = 0;
        System.out.println();
        System.out.printf("latency of the requests started after the first %d s (the JVM warming up)%n",
                options.warmupSeconds());
        System.out.println("kind          status    count   p50 ms   p90 ms   p99 ms   max ms");
        for (Map.Entry<String, Latencies> row : new TreeMap<>(latencies).entrySet()) {
            String[] kindStatus = row.getKey().split(" ");
            long[] sorted = row.getValue().sorted();
            int count = row.getValue().count();
            if (sorted.length == 0) {
                System.out.printf("%-13s %6s %8d%n", kindStatus[0], kindStatus[1], count);
            } else {
                System.out.printf(Locale.ROOT, "%-13s %6s %8d %8.1f %8.1f %8.1f %8.1f%n", kindStatus[0],
                        kindStatus[1], count, pct(sorted, 50), pct(sorted, 90), pct(sorted, 99),
                        sorted[sorted.length - 1] / 1e6);
            }
            if (!kindStatus[0].equals("health") && !kindStatus[0].startsWith("mesh-")) {
                requests += count;
            }
            if (row.getKey().equals("render 200")) {
                renders += count;
            }
            busy += kindStatus[1].equals("503") ? count : 0;
            full += kindStatus[1].equals("429") ? count : 0;
        }
        Map<String, Long> states = new TreeMap<>();
        for (String state : jobs.values()) {
            states.merge(state.isEmpty() ? "not final" : state, 1L, Long::sum);
        }
        long done = states.getOrDefault("done", 0L);
        System.out.println();
        System.out.printf(Locale.ROOT, "%.1f s of load (%d s, then finishing the jobs in flight)%n", seconds,
                options.seconds());
        System.out.printf(Locale.ROOT, "throughput: %.1f requests/s; %.1f renders/s (%d synchronous + %d jobs done)%n",
                requests / seconds, (renders + done) / seconds, renders, done);
        System.out.printf("jobs accepted: %d %s%n", jobs.size(), states);
        System.out.printf("429: %d, 503: %d; retries after Retry-After: %d; given up at the end: %d%n", full, busy,
                retryWaits.get(), gaveUp.get());
        if (!options.keys().isEmpty() || greedyGroup != null) {
            reportPrincipals(seconds);
        }
        System.out.printf("then %d mesh jobs (%,d triangles each), one at a time, and %d s idle%n", options.meshJobs(),
                2 * MESH_GRID * MESH_GRID, options.idleSeconds());
        System.out.printf(Locale.ROOT, "heap: %.1f MiB before, %.1f MiB after (limit %.1f)%n", mib(before.heap),
                mib(after.heap), mib(before.heap + margin));
        System.out.printf("threads: %d before, %d after (limit %d)%n", before.threads, after.threads, threadCeiling);
        System.out.println();
        if (problems.isEmpty()) {
            System.out.println("PASS: no 5xx, every 429/503 had Retry-After, 400 only for invalid scenes, "
                    + "every job final, health UP, heap and threads back");
        } else {
            System.out.println("FAIL: " + problems.count() + " problems; the first ones:");
            problems.first(30).forEach(p -> System.out.println("  " + p));
        }
    }

    /**
     * Per principal (the greedy clients a row of their own): job submissions and their answers, what
     * the 429s named, the wait from a job's first submission to its 202 (retries included), and the
     * synchronous renders answered 200 out of all answered.
     */
    private void reportPrincipals(double seconds) {
        System.out.println();
        System.out.println("per principal: job submissions (every answer; 429s by what they named: the principal's own limit,");
        System.out.println("the server's queue, anything else), the wait from a job's first submission to its 202 (retries");
        System.out.println("included, after the warm-up), synchronous renders answered 200 of all answered and their latency");
        System.out.println("principal          clients submits accepted  acc/s  202%  429-limit 429-queue 429-other  503 gave-up"
                + "  wait-p50 wait-p99  renders 200%  r-p50  r-p99");
        Map<String, Long> named = new TreeMap<>();
        for (Group g : groups) {
            int submits = 0;
            for (String kindStatus : g.latencies.keySet()) {
                submits += kindStatus.startsWith("job-submit ") ? g.count(kindStatus) : 0;
            }
            long limit = g.refused("job-submit", "429", "principal-limit");
            long queue = g.refused("job-submit", "429", "queue");
            long all429 = g.refused("job-submit", "429", null);
            long busy = g.refused("job-submit", "503", null);
            long[] wait = g.acceptWait.sorted();
            int rendered = g.count("render 200");
            int renderAnswers = 0;
            for (String kindStatus : g.latencies.keySet()) {
                renderAnswers += kindStatus.startsWith("render ") ? g.count(kindStatus) : 0;
            }
            long[] render = g.sorted("render 200");
            System.out.printf(Locale.ROOT, "%-18s %7d %8d %8d %6.1f %4s %10d %9d %9d %4d %7d %9s %8s %8d %4s %6s %6s%n",
                    abbreviateName(g.name), g.clients, submits, g.accepted.get(), g.accepted.get() / seconds,
                    share(g.accepted.get(), submits), limit, queue, all429 - limit - queue, busy, g.gaveUp.get(),
                    ms(wait, 50), ms(wait, 99), rendered, share(rendered, renderAnswers), ms(render, 50),
                    ms(render, 99));
            for (Map.Entry<String, AtomicLong> refusal : g.refusals.entrySet()) {
                named.merge(refusal.getKey(), refusal.getValue().get(), Long::sum);
            }
        }
        System.out.println("429s and 503s by what they named (all principals): " + (named.isEmpty() ? "none" : named));
    }

    private static String abbreviateName(String name) {
        return name.length() <= 18 ? name : name.substring(0, 17) + "~";
    }

    private static String share(long part, long whole) {
        return whole == 0 ? "-" : Math.round(100.0 * part / whole) + "%";
    }

    private static String ms(long[] sorted, int percent) {
        return sorted.length == 0 ? "-" : String.format(Locale.ROOT, "%.0f", pct(sorted, percent));
    }

    private static double pct(long[] sorted, int percent) {
        int rank = (int) Math.ceil(percent / 100.0 * sorted.length);
        return sorted[Math.max(0, rank - 1)] / 1e6;
    }

    private static double mib(long bytes) {
        return bytes / (1024.0 * 1024.0);
    }

    private static String body(HttpResponse<byte[]> response) {
        return new String(response.body(), StandardCharsets.UTF_8);
    }

    private static String abbreviate(String text) {
        return text.length() <= 300 ? text : text.substring(0, 300) + "...";
    }

    /** "status, tile x12, end" */
    private static String summary(List<String> names) {
        StringBuilder out = new StringBuilder();
        for (int i = 0; i < names.size(); ) {
            int j = i;
            while (j < names.size() && names.get(j).equals(names.get(i))) {
                j++;
            }
            out.append(out.length() > 0 ? ", " : "").append(names.get(i)).append(j - i > 1 ? " x" + (j - i) : "");
            i = j;
        }
        return out.length() > 0 ? out.toString() : "nothing";
    }

    /** Closes an event stream at the deadline, unless interrupted first. */
    static final class Watchdog {
        private Watchdog() {
        }

        static Thread start(InputStream stream, long deadlineNanos) {
            Thread watchdog = new Thread(() -> {
                try {
                    TimeUnit.NANOSECONDS.sleep(Math.max(0, deadlineNanos - System.nanoTime()));
                    stream.close();
                } catch (InterruptedException | IOException e) {
                    // the stream ended first
                }
            }, "sse-watchdog");
            watchdog.setDaemon(true);
            watchdog.start();
            return watchdog;
        }
    }

    /** Who a client thread sends as: the index of its key, and its row in the report (null: none). */
    record Caller(int keyIndex, Group group) {
    }

    /** One principal's polite clients, or the greedy ones: their answers, job submissions and refusals. */
    static final class Group {
        final String name;
        final int keyIndex;
        final boolean greedy;
        int clients;
        final Map<String, Latencies> latencies = new ConcurrentHashMap<>();
        /** "kind status named", e.g. "job-submit 429 principal-limit" */
        final Map<String, AtomicLong> refusals = new ConcurrentHashMap<>();
        final AtomicLong accepted = new AtomicLong(), gaveUp = new AtomicLong();
        /** From a job's first submission to its 202, retries included. */
        final Latencies acceptWait = new Latencies();

        Group(String name, int keyIndex, boolean greedy) {
            this.name = name;
            this.keyIndex = keyIndex;
            this.greedy = greedy;
        }

        int count(String kindStatus) {
            Latencies l = latencies.get(kindStatus);
            return l == null ? 0 : l.count();
        }

        long refused(String kind, String status, String named) {
            long sum = 0;
            for (Map.Entry<String, AtomicLong> refusal : refusals.entrySet()) {
                String[] parts = refusal.getKey().split(" ");
                if (parts[0].equals(kind) && (status == null || parts[1].equals(status))
                        && (named == null || parts[2].equals(named))) {
                    sum += refusal.getValue().get();
                }
            }
            return sum;
        }

        long[] sorted(String kindStatus) {
            Latencies l = latencies.get(kindStatus);
            return l == null ? new long[0] : l.sorted();
        }
    }

    /** How many answers of one kind and status, and the latencies of those timed, in nanoseconds. */
    static final class Latencies {
        private long[] values = new long[256];
        private int size, count;

        synchronized void add(long nanos, boolean timed) {
            count++;
            if (!timed) {
                return;
            }
            if (size == values.length) {
                values = Arrays.copyOf(values, size * 2);
            }
            values[size++] = nanos;
        }

        synchronized int count() {
            return count;
        }

        synchronized long[] sorted() {
            long[] copy = Arrays.copyOf(values, size);
            Arrays.sort(copy);
            return copy;
        }
    }

    /** Failed checks: all counted, the first kept. */
    static final class Problems {
        private final ConcurrentLinkedQueue<String> first = new ConcurrentLinkedQueue<>();
        private final AtomicLong count = new AtomicLong();

        void add(String problem) {
            if (count.incrementAndGet() <= 100) {
                first.add(problem);
            }
        }

        boolean isEmpty() {
            return count.get() == 0;
        }

        long count() {
            return count.get();
        }

        List<String> first(int n) {
            return first.stream().limit(n).toList();
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

        static String string(Map<String, Object> object, String key) {
            Object value = object.get(key);
            return value instanceof String s ? s : null;
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
                out.append(value); // Num, Integer, Boolean, null
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

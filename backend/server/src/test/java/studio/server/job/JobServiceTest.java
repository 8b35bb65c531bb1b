package studio.server.job;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.ref.WeakReference;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BooleanSupplier;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import studio.server.scene.compiling.CompileRequest;
import studio.engine.scene.Scene;
import studio.server.Await;
import studio.server.render.RenderBudget;
import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.examples.ExampleSceneFiles;
import studio.server.scene.format.InvalidSceneException;
import studio.server.system.IntakeMemory;
import studio.server.system.MemoryBudget;

class JobServiceTest {

    /** 64x48: 12 tiles of 16 pixels, fast. */
    static final String SMALL = scene(64, 48, 1);
    /** Big enough to still be running when the test acts on it (many tiles, many samples). */
    static final String LARGE = scene(1024, 768, 256);

    static String scene(int width, int height, int samples) {
        return """
                {"name": "job-test", "image": {"width": %d, "height": %d},
                 "render": {"samples": %d},
                 "objects": [{"type": "sphere", "material": {"type": "glass"}}, {"type": "plane"}]}
                """.formatted(width, height, samples);
    }

    static CompiledScene compile(String json) {
        return ExampleSceneFiles.compiler().compile(CompileRequest.of(json.getBytes(StandardCharsets.UTF_8)));
    }

    private JobService service;

    private JobService service(JobSettings settings) {
        service = new JobService(ExampleSceneFiles.compiler(), settings);
        return service;
    }

    private static JobSettings settings(int concurrent, int queue) {
        return new JobSettings(concurrent, queue, Duration.ofMinutes(10), 50, Duration.ofMinutes(10), 2);
    }

    @AfterEach
    void stop() {
        if (service != null) {
            service.shutdown(10_000);
        }
    }

    static void await(String what, BooleanSupplier condition) throws Exception {
        Await.until(what, 30_000, condition::getAsBoolean);
    }

    @Test
    void jobGoesFromQueuedThroughRunningToDoneWithItsImage() throws Exception {
        JobService jobs = service(settings(1, 4));
        JobStatus started = jobs.submit(JobRequests.of(compile(SMALL)));
        assertTrue(started.state() == JobState.QUEUED || started.state() == JobState.RUNNING, started.toString());
        assertEquals("job-test.png", started.fileName());
        await("done", () -> jobs.status(started.id()).state() == JobState.DONE);
        JobStatus done = jobs.status(started.id());
        assertEquals(1.0, done.progress());
        assertNotNull(done.raysPerSecond());
        assertTrue(done.raysPerSecond() > 0);
        byte[] png = jobs.image(started.id()).bytes();
        assertArrayEquals(new byte[] {(byte) 0x89, 'P', 'N', 'G'}, java.util.Arrays.copyOf(png, 4));
    }

    /**
     * In a cluster a job reports its end only once the cluster has it (other members answer from the
     * cluster's maps), and serves its image while the cluster learns the end: a client that heard
     * "done" through another member gets the image from this one too.
     */
    @Test
    void jobReportsItsEndOnlyOnceTheClusterHasItAndServesItsImageMeanwhile() throws Exception {
        List<String> seenWhileEnding = new CopyOnWriteArrayList<>();
        JobService[] self = new JobService[1];
        JobCluster cluster = new JobCluster() {
            @Override
            public void ending(String id, JobStatus end, byte[] image) {
                JobService jobs = self[0];
                seenWhileEnding.add(end.state() + " told, " + jobs.status(id).state() + " reported, image "
                        + (java.util.Arrays.equals(jobs.image(id).bytes(), image) ? "served" : "differs"));
            }
        };
        service = self[0] = new JobService(settings(1, 4), RenderBudget.unlimited(), Duration.ofSeconds(5), cluster);
        JobStatus started = service.submit(JobRequests.of(compile(SMALL)));

        await("done", () -> service.status(started.id()).state() == JobState.DONE);

        assertEquals(List.of("DONE told, RUNNING reported, image served"), seenWhileEnding);
    }

    @Test
    void listenerHearsEachStateEveryTileAndTheEnd() throws Exception {
        JobService jobs = service(settings(1, 4));
        JobStatus blocker = jobs.submit(JobRequests.of(compile(LARGE)));
        JobStatus small = jobs.submit(JobRequests.of(compile(SMALL)));
        Recorder recorder = new Recorder();
        jobs.subscribe(small.id(), recorder);
        jobs.cancel(blocker.id());
        await("end", () -> recorder.ended != null);
        assertEquals(List.of("status:queued", "status:running"), recorder.events.subList(0, 2));
        assertEquals(JobState.DONE, recorder.ended.state());
        List<String> tiles = recorder.events.stream().filter(e -> e.startsWith("tile:")).sorted().toList();
        // 64 x 48 in tiles of 32 would be 4, too few for the threads: the renderer halves them
        assertEquals(List.of("tile:0,0", "tile:0,16", "tile:0,32", "tile:16,0", "tile:16,16", "tile:16,32",
                "tile:32,0", "tile:32,16", "tile:32,32", "tile:48,0", "tile:48,16", "tile:48,32"), tiles);
        assertEquals(2 + tiles.size() + 1, recorder.events.size(), recorder.events.toString());
        assertEquals("end:done", recorder.events.get(recorder.events.size() - 1));
        // progress counts the tiles sent, one more each time, on two render threads too (it went by
        // the renderer's count, which two threads can deliver out of order: a step back)
        for (int i = 0; i < recorder.progress.size(); i++) {
            assertEquals((i + 1) / 12.0, recorder.progress.get(i), 1e-12, "tile event " + i);
        }
    }

    @Test
    void lateSubscriberGetsTheTilesFinishedSoFar() throws Exception {
        JobService jobs = service(settings(1, 4));
        JobStatus started = jobs.submit(JobRequests.of(compile(LARGE)));
        await("a few tiles", () -> jobs.status(started.id()).progress() > 0.02);
        double progress = jobs.status(started.id()).progress();
        Recorder late = new Recorder();
        jobs.subscribe(started.id(), late);
        await("the tiles so far", () -> late.events.stream().filter(e -> e.startsWith("tile:")).count()
                >= Math.round(progress * 768));
        assertEquals("status:running", late.events.get(0));
        jobs.cancel(started.id());
    }

    @Test
    void cancellingARunningJobStopsItWithinATile() throws Exception {
        JobService jobs = service(settings(1, 4));
        JobStatus started = jobs.submit(JobRequests.of(compile(LARGE)));
        await("running", () -> jobs.status(started.id()).progress() > 0);
        long before = System.nanoTime();
        jobs.cancel(started.id());
        await("cancelled", () -> jobs.status(started.id()).state() == JobState.CANCELLED);
        long millis = (System.nanoTime() - before) / 1_000_000;
        assertTrue(millis < 5_000, "took " + millis + " ms to stop");
        assertTrue(jobs.status(started.id()).progress() < 1);
        assertThrows(JobNotDoneException.class, () -> jobs.image(started.id()));
    }

    @Test
    void cancellingAQueuedJobEndsItAtOnce() throws Exception {
        JobService jobs = service(settings(1, 4));
        JobStatus running = jobs.submit(JobRequests.of(compile(LARGE)));
        JobStatus queued = jobs.submit(JobRequests.of(compile(SMALL)));
        assertEquals(JobState.QUEUED, queued.state());
        assertEquals(JobState.CANCELLED, jobs.cancel(queued.id()).state());
        jobs.cancel(running.id());
    }

    @Test
    void aFullQueueIsRefusedBeforeAnySceneIsRead() throws Exception {
        JobService jobs = service(settings(1, 1));
        jobs.checkRoom();
        JobStatus running = jobs.submit(JobRequests.of(compile(LARGE)));
        await("running", () -> jobs.status(running.id()).state() == JobState.RUNNING);
        jobs.checkRoom(); // the queue's one place is free
        JobStatus queued = jobs.submit(JobRequests.of(compile(LARGE)));
        JobQueueFullException full = assertThrows(JobQueueFullException.class, jobs::checkRoom);
        assertTrue(full.retryAfterSeconds() >= 1);
        jobs.cancel(queued.id());
        jobs.checkRoom();
        jobs.cancel(running.id());
    }

    /** As POST /api/jobs starts a job: the service reads the scene, once there is room for it. */
    @Test
    void startReadsTheSceneOnlyOnceThereIsRoom() throws Exception {
        JobService jobs = service(settings(1, 1));
        JobStatus running = jobs.start(SMALL.getBytes(StandardCharsets.UTF_8), IntakeMemory.NONE, JobOwner.ANYONE);
        await("done", () -> jobs.status(running.id()).state() == JobState.DONE);
        assertNotNull(jobs.image(running.id()).bytes());
        InvalidSceneException invalid = assertThrows(InvalidSceneException.class,
                () -> jobs.start("{}".getBytes(StandardCharsets.UTF_8), IntakeMemory.NONE, JobOwner.ANYONE));
        assertEquals("objects", invalid.problems().get(0).field());

        JobStatus blocker = jobs.submit(JobRequests.of(compile(LARGE)));
        await("running", () -> jobs.status(blocker.id()).state() == JobState.RUNNING);
        JobStatus queued = jobs.submit(JobRequests.of(compile(LARGE)));
        // no room: refused before the scene is read, so an invalid one is refused for the queue, not itself
        assertThrows(JobQueueFullException.class, () -> jobs.start("{}".getBytes(StandardCharsets.UTF_8),
                IntakeMemory.NONE, JobOwner.ANYONE));
        jobs.cancel(queued.id());
        jobs.cancel(blocker.id());
    }

    @Test
    void fullQueueIsRefusedWithARetryDelay() {
        JobService jobs = service(settings(1, 1));
        JobStatus running = jobs.submit(JobRequests.of(compile(LARGE)));
        jobs.submit(JobRequests.of(compile(LARGE)));
        JobQueueFullException full = assertThrows(JobQueueFullException.class, () -> jobs.submit(JobRequests.of(compile(SMALL))));
        assertTrue(full.retryAfterSeconds() >= 1);
        jobs.cancel(running.id());
    }

    @Test
    void finishedJobsExpireAfterTheirKeepTime() throws Exception {
        JobService jobs = service(new JobSettings(1, 4, Duration.ZERO, 50, Duration.ofMinutes(10), 2));
        JobStatus started = jobs.submit(JobRequests.of(compile(SMALL)));
        await("done", () -> jobs.status(started.id()).state() == JobState.DONE);
        Thread.sleep(2);
        jobs.sweep();
        assertThrows(JobNotFoundException.class, () -> jobs.status(started.id()));
    }

    @Test
    void onlyTheNewestFinishedJobsAreKept() throws Exception {
        JobService jobs = service(new JobSettings(1, 4, Duration.ofMinutes(10), 1, Duration.ofMinutes(10), 2));
        JobStatus first = jobs.submit(JobRequests.of(compile(SMALL)));
        await("first done", () -> jobs.status(first.id()).state() == JobState.DONE);
        JobStatus second = jobs.submit(JobRequests.of(compile(SMALL)));
        await("second done", () -> jobs.status(second.id()).state() == JobState.DONE);
        jobs.sweep();
        assertThrows(JobNotFoundException.class, () -> jobs.status(first.id()));
        assertEquals(JobState.DONE, jobs.status(second.id()).state());
    }

    @Test
    void jobNobodyAsksAboutIsCancelled() throws Exception {
        JobService jobs = service(new JobSettings(1, 4, Duration.ofMinutes(10), 50, Duration.ofMillis(50), 2));
        JobStatus started = jobs.submit(JobRequests.of(compile(LARGE)));
        Thread.sleep(100);
        jobs.sweep();
        await("cancelled", () -> jobs.status(started.id()).state() == JobState.CANCELLED);
    }

    @Test
    void jobWithAnOpenEventStreamIsNotAbandoned() throws Exception {
        JobService jobs = service(new JobSettings(1, 4, Duration.ofMinutes(10), 50, Duration.ofMillis(50), 2));
        JobStatus started = jobs.submit(JobRequests.of(compile(LARGE)));
        jobs.subscribe(started.id(), new Recorder());
        Thread.sleep(100);
        jobs.sweep();
        assertEquals(JobState.RUNNING, jobs.status(started.id()).state());
        jobs.cancel(started.id());
    }

    @Test
    void finishedJobKeepsItsImageButNotItsScene() throws Exception {
        // a kept job (up to 50, for 15 minutes) holding its geometry held ~25 MB per 200,000-triangle scene
        JobService jobs = service(settings(1, 4));
        CompiledScene first = compile(SMALL), second = compile(SMALL);
        WeakReference<Scene> doneScene = new WeakReference<>(first.scene());
        WeakReference<Scene> cancelledScene = new WeakReference<>(second.scene());
        JobStatus done = jobs.submit(JobRequests.of(first));
        JobStatus cancelled = jobs.submit(JobRequests.of(second));
        first = null;
        second = null;
        jobs.cancel(cancelled.id());
        await("both final", () -> jobs.status(done.id()).state().isFinal()
                && jobs.status(cancelled.id()).state().isFinal());
        await("their scenes collected", () -> {
            System.gc();
            return doneScene.get() == null && cancelledScene.get() == null;
        });
        assertEquals(JobState.DONE, jobs.status(done.id()).state());
        assertEquals("job-test.png", jobs.status(done.id()).fileName());
        assertTrue(jobs.image(done.id()).bytes().length > 0);
    }

    @Test
    void unknownJobIsNotFound() {
        JobService jobs = service(settings(1, 4));
        assertThrows(JobNotFoundException.class, () -> jobs.status("nope"));
        assertThrows(JobNotFoundException.class, () -> jobs.cancel("nope"));
        assertThrows(JobNotFoundException.class, () -> jobs.image("nope"));
    }

    // --- memory, disconnects, shutdown ---------------------------------------------------------

    private JobService service(JobSettings settings, MemoryBudget memory, Duration grace) {
        service = new JobService(ExampleSceneFiles.compiler(), settings, new RenderBudget(Duration.ofMinutes(5), memory),
                grace, JobCluster.SINGLE);
        return service;
    }

    @Test
    void jobHoldsItsRenderMemoryUntilItEndsThenOnlyItsImage() throws Exception {
        MemoryBudget memory = new MemoryBudget(1L << 30);
        JobService jobs = service(settings(1, 4), memory, Duration.ofSeconds(5));
        // long enough (a few hundred ms) to be running still when the reservation is read: SMALL
        // could finish first, leaving only its image (seen once)
        JobStatus started = jobs.submit(JobRequests.of(compile(scene(320, 240, 64))));
        assertTrue(memory.reserved() > 320 * 240 * 40, "reserved " + memory.reserved());
        await("done", () -> jobs.status(started.id()).state() == JobState.DONE);
        assertEquals(jobs.image(started.id()).bytes().length, memory.reserved());
    }

    @Test
    void jobThatDoesNotFitTheFreeMemoryIsRefusedWithARetryDelay() {
        // LARGE needs about 4 MiB + 1024 x 768 x 66 bytes = 54 MiB; two do not fit in 64 MiB
        MemoryBudget memory = new MemoryBudget(64L << 20);
        JobService jobs = service(settings(1, 4), memory, Duration.ofSeconds(5));
        JobStatus running = jobs.submit(JobRequests.of(compile(LARGE)));
        JobQueueFullException full = assertThrows(JobQueueFullException.class, () -> jobs.submit(JobRequests.of(compile(LARGE))));
        assertTrue(full.getMessage().contains("memory"), full.getMessage());
        assertTrue(full.retryAfterSeconds() >= 1);
        jobs.cancel(running.id());
    }

    @Test
    void jobThatCouldNeverFitIsInvalid() {
        JobService jobs = service(settings(1, 4), new MemoryBudget(8L << 20), Duration.ofSeconds(5));
        InvalidSceneException invalid = assertThrows(InvalidSceneException.class, () -> jobs.submit(JobRequests.of(compile(LARGE))));
        assertEquals("image", invalid.problems().get(0).field());
    }

    @Test
    void droppedJobGivesItsMemoryBack() throws Exception {
        MemoryBudget memory = new MemoryBudget(1L << 30);
        JobService jobs = service(new JobSettings(1, 4, Duration.ZERO, 50, Duration.ofMinutes(10), 2), memory,
                Duration.ofSeconds(5));
        JobStatus started = jobs.submit(JobRequests.of(compile(SMALL)));
        await("done", () -> jobs.status(started.id()).state() == JobState.DONE);
        Thread.sleep(2);
        jobs.sweep();
        assertEquals(0, memory.reserved());
    }

    @Test
    void lastWatcherDisconnectingCancelsTheJob() throws Exception {
        JobService jobs = service(settings(1, 4));
        JobStatus started = jobs.submit(JobRequests.of(compile(LARGE)));
        Recorder first = new Recorder(), second = new Recorder();
        jobs.subscribe(started.id(), first);
        jobs.subscribe(started.id(), second);
        jobs.disconnected(started.id(), first);
        assertTrue(!jobs.status(started.id()).state().isFinal(), "another client still watches");
        jobs.disconnected(started.id(), second);
        await("cancelled", () -> jobs.status(started.id()).state() == JobState.CANCELLED);
    }

    @Test
    void shutdownLetsARunningJobFinishWithinTheGrace() throws Exception {
        JobService jobs = service(settings(1, 4));
        JobStatus started = jobs.submit(JobRequests.of(compile(scene(256, 192, 4))));
        await("running", () -> jobs.status(started.id()).state() == JobState.RUNNING);
        jobs.shutdown(30_000);
        assertEquals(JobState.DONE, jobs.status(started.id()).state());
        assertThrows(JobQueueFullException.class, () -> jobs.submit(JobRequests.of(compile(SMALL))));
    }

    @Test
    void shutdownCancelsQueuedJobsAtOnceAndRunningOnesAfterTheGrace() throws Exception {
        JobService jobs = service(settings(1, 4));
        JobStatus running = jobs.submit(JobRequests.of(compile(LARGE)));
        JobStatus queued = jobs.submit(JobRequests.of(compile(SMALL)));
        await("running", () -> jobs.status(running.id()).progress() > 0);
        long start = System.nanoTime();
        jobs.shutdown(300);
        long millis = (System.nanoTime() - start) / 1_000_000;
        assertEquals(JobState.CANCELLED, jobs.status(queued.id()).state());
        JobStatus stopped = jobs.status(running.id());
        assertEquals(JobState.CANCELLED, stopped.state());
        assertTrue(stopped.error().contains("shut down"), stopped.error());
        assertTrue(millis < 300 + studio.server.system.Drainable.CANCEL_WAIT_MILLIS, "shutdown took " + millis + " ms");
        assertThrows(JobNotDoneException.class, () -> jobs.image(running.id()));
    }

    // --- listeners that stop reading ------------------------------------------------------------

    @Test
    void listenerThatStopsReadingHoldsUpNeitherTheJobNorItsStatusAndIsDropped() throws Exception {
        JobService jobs = service(settings(1, 4));
        JobStatus started = jobs.submit(JobRequests.of(compile(scene(512, 384, 16))));
        Stuck stuck = new Stuck();
        Recorder reading = new Recorder();
        jobs.subscribe(started.id(), stuck);
        jobs.subscribe(started.id(), reading);
        try {
            await("the stuck listener inside its first tile", () -> stuck.inside);
            long stuckAt = System.nanoTime();
            // the render thread wrote to the stuck listener under the job's lock: status waited for it
            while (!jobs.status(started.id()).state().isFinal()) {
                long before = System.nanoTime();
                jobs.status(started.id());
                long millis = (System.nanoTime() - before) / 1_000_000;
                assertTrue(millis < 1_000, "status took " + millis + " ms");
                Thread.sleep(20);
            }
            assertEquals(JobState.DONE, jobs.status(started.id()).state(), "the job goes on without the stuck listener");
            await("the reading listener's end", () -> reading.ended != null);
            assertEquals(JobState.DONE, reading.ended.state());
            await("the stuck listener dropped", () -> !jobs.job(started.id()).hasListeners());
            long droppedAfter = (System.nanoTime() - stuckAt) / 1_000_000;
            assertTrue(droppedAfter >= JobRegistry.STALL_MILLIS - 1_000, "dropped after " + droppedAfter + " ms");
        } finally {
            stuck.release.countDown();
        }
        await("the stuck listener told it was dropped", () -> stuck.dropped);
        assertEquals(null, stuck.ended, "a dropped listener hears no end");
    }

    @Test
    void shutdownTellsTheListenersOfRunningAndQueuedJobsTheirEnd() throws Exception {
        JobService jobs = service(settings(1, 4));
        JobStatus running = jobs.submit(JobRequests.of(compile(LARGE)));
        JobStatus queued = jobs.submit(JobRequests.of(compile(SMALL)));
        Recorder watchingRunning = new Recorder(), watchingQueued = new Recorder();
        jobs.subscribe(running.id(), watchingRunning);
        jobs.subscribe(queued.id(), watchingQueued);
        await("running", () -> jobs.status(running.id()).progress() > 0);
        jobs.stopAccepting();
        await("the queued job's end, at once", () -> watchingQueued.ended != null);
        assertEquals(JobState.CANCELLED, watchingQueued.ended.state());
        assertEquals(null, watchingRunning.ended, "the running job goes on for its grace period");
        assertThrows(JobQueueFullException.class, () -> jobs.submit(JobRequests.of(compile(SMALL))));
        jobs.cancelRunning(System.nanoTime() + 5_000_000_000L);
        assertEquals(JobState.CANCELLED, watchingRunning.ended.state());
        assertTrue(watchingRunning.ended.error().contains("shut down"), watchingRunning.ended.error());
    }

    /** A listener whose client stops reading: its first tile blocks until released (a minute at most). */
    static final class Stuck implements JobListener {
        final java.util.concurrent.CountDownLatch release = new java.util.concurrent.CountDownLatch(1);
        volatile boolean inside, dropped;
        volatile JobStatus ended;

        @Override
        public void status(JobStatus status) {
        }

        @Override
        public void tile(TileEvent tile) {
            inside = true;
            try {
                release.await(60, java.util.concurrent.TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }

        @Override
        public void end(JobStatus status) {
            ended = status;
        }

        @Override
        public void dropped() {
            dropped = true;
        }
    }

    /** Records events as "status:running", "tile:x,y", "end:done". */
    static final class Recorder implements JobListener {
        final List<String> events = new CopyOnWriteArrayList<>();
        final List<Double> progress = new CopyOnWriteArrayList<>();
        volatile JobStatus ended;

        @Override
        public void status(JobStatus status) {
            events.add("status:" + status.state().json());
        }

        @Override
        public void tile(TileEvent tile) {
            assertTrue(tile.png().length() > 0);
            events.add("tile:" + tile.x() + "," + tile.y());
            progress.add(tile.progress());
        }

        @Override
        public void end(JobStatus status) {
            events.add("end:" + status.state().json());
            ended = status;
        }
    }
}

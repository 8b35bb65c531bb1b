package studio.server.job;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.springframework.boot.test.system.CapturedOutput;
import org.springframework.boot.test.system.OutputCaptureExtension;

import studio.server.scene.compiling.CompiledScene;
import studio.server.scene.examples.ExampleSceneFiles;

/**
 * Submits racing for the last places of the queue: each is accepted or refused with 429, never
 * accepted and then failed as if the server were stopping.
 */
@ExtendWith(OutputCaptureExtension.class)
class JobAdmissionRaceTest {

    private static final int THREADS = 8, ROUNDS = 30;

    @Test
    void racingSubmitsAreAcceptedOrRefusedNeverFailed(CapturedOutput output) throws Exception {
        JobService jobs = new JobService(ExampleSceneFiles.compiler(),
                new JobSettings(1, 2, Duration.ofMinutes(10), 500, Duration.ofMinutes(10), 1));
        CompiledScene large = JobServiceTest.compile(JobServiceTest.LARGE);
        List<String> accepted = new CopyOnWriteArrayList<>();
        List<Throwable> unexpected = new CopyOnWriteArrayList<>();
        try {
            for (int round = 0; round < ROUNDS; round++) {
                CyclicBarrier start = new CyclicBarrier(THREADS);
                Thread[] threads = new Thread[THREADS];
                for (int t = 0; t < THREADS; t++) {
                    threads[t] = new Thread(() -> {
                        try {
                            start.await(10, TimeUnit.SECONDS);
                            accepted.add(jobs.submit(large).id());
                        } catch (JobQueueFullException refused) {
                            // the answer a client gets: 429
                        } catch (Throwable e) {
                            unexpected.add(e);
                        }
                    });
                    threads[t].start();
                }
                for (Thread thread : threads) {
                    thread.join(30_000);
                }
                for (String id : accepted) {
                    assertThat(jobs.status(id).state()).isNotEqualTo(JobState.FAILED);
                    jobs.cancel(id);
                }
                assertThat(accepted).hasSizeLessThanOrEqualTo(3);
                accepted.clear();
            }
        } finally {
            jobs.shutdown(10_000);
        }
        assertThat(unexpected).isEmpty();
        assertThat(output.getAll()).doesNotContain("shutting down");
    }

    @Test
    void racingSubmitsOfOnePrincipalNeverPassTheirLimit() throws Exception {
        JobService jobs = new JobService(ExampleSceneFiles.compiler(),
                new JobSettings(1, 8, Duration.ofMinutes(10), 500, Duration.ofMinutes(10), 1));
        CompiledScene large = JobServiceTest.compile(JobServiceTest.LARGE);
        JobOwner alice = new JobOwner("alice", 2);
        List<String> accepted = new CopyOnWriteArrayList<>();
        try {
            for (int round = 0; round < ROUNDS; round++) {
                CyclicBarrier start = new CyclicBarrier(THREADS);
                Thread[] threads = new Thread[THREADS];
                for (int t = 0; t < THREADS; t++) {
                    threads[t] = new Thread(() -> {
                        try {
                            start.await(10, TimeUnit.SECONDS);
                            accepted.add(jobs.submit(large, null, studio.server.system.IntakeMemory.NONE, alice).id());
                        } catch (Exception refused) {
                            // 429: the principal's limit
                        }
                    });
                    threads[t].start();
                }
                for (Thread thread : threads) {
                    thread.join(30_000);
                }
                assertThat(accepted).hasSizeLessThanOrEqualTo(2);
                for (String id : accepted) {
                    jobs.cancel(id, "alice");
                }
                accepted.clear();
            }
        } finally {
            jobs.shutdown(10_000);
        }
    }
}

package studio.server.job;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.Callable;
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
 * Submits racing for the last places of the queue, or of one principal's share: each is accepted
 * or refused with 429, never accepted and then failed as if the server were stopping, and never
 * beyond the limit.
 */
@ExtendWith(OutputCaptureExtension.class)
class JobAdmissionRaceTest {

    private static final int THREADS = 8, ROUNDS = 30;

    /** {@value #THREADS} threads submit at once; the ids accepted (a refusal is a {@link JobQueueFullException}). */
    private static List<String> race(Callable<String> submit, List<Throwable> unexpected) throws InterruptedException {
        List<String> accepted = new CopyOnWriteArrayList<>();
        CyclicBarrier start = new CyclicBarrier(THREADS);
        Thread[] threads = new Thread[THREADS];
        for (int t = 0; t < THREADS; t++) {
            threads[t] = new Thread(() -> {
                try {
                    start.await(10, TimeUnit.SECONDS);
                    accepted.add(submit.call());
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
        return accepted;
    }

    private static JobService service(int queue) {
        return new JobService(ExampleSceneFiles.compiler(),
                new JobSettings(1, queue, Duration.ofMinutes(10), 500, Duration.ofMinutes(10), 1));
    }

    @Test
    void racingSubmitsAreAcceptedOrRefusedNeverFailed(CapturedOutput output) throws Exception {
        JobService jobs = service(2);
        CompiledScene large = JobServiceTest.compile(JobServiceTest.LARGE);
        List<Throwable> unexpected = new CopyOnWriteArrayList<>();
        try {
            for (int round = 0; round < ROUNDS; round++) {
                List<String> accepted = race(() -> jobs.submit(JobRequests.of(large)).id(), unexpected);
                for (String id : accepted) {
                    assertThat(jobs.status(id).state()).isNotEqualTo(JobState.FAILED);
                    jobs.cancel(id);
                }
                assertThat(accepted).hasSizeLessThanOrEqualTo(3);
            }
        } finally {
            jobs.shutdown(10_000);
        }
        assertThat(unexpected).isEmpty();
        assertThat(output.getAll()).doesNotContain("shutting down");
    }

    @Test
    void racingSubmitsOfOnePrincipalNeverPassTheirLimit() throws Exception {
        JobService jobs = service(8);
        CompiledScene large = JobServiceTest.compile(JobServiceTest.LARGE);
        JobOwner alice = new JobOwner("alice", 2);
        List<Throwable> unexpected = new CopyOnWriteArrayList<>();
        try {
            for (int round = 0; round < ROUNDS; round++) {
                List<String> accepted = race(() -> jobs.submit(JobRequests.of(large, null, alice)).id(), unexpected);
                assertThat(accepted).hasSizeLessThanOrEqualTo(2);
                for (String id : accepted) {
                    jobs.cancel(id, "alice");
                }
            }
        } finally {
            jobs.shutdown(10_000);
        }
        assertThat(unexpected).isEmpty();
    }
}

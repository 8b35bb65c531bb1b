package studio.server.system;

import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Work that the service lets finish on shutdown (see {@link GracefulShutdown}): it stops taking
 * more, then its work in hand ends or, after the grace period, is cancelled, within deadlines.
 */
public interface Drainable {

    /** After cancelling, how long the work gets to stop and its clients to hear it. */
    long CANCEL_WAIT_MILLIS = 5_000;

    /** Refuses new work from now on; work that has not started ends at once. */
    void stopAccepting();

    /**
     * Waits until the work in hand has ended and its clients have had their answers, at most until
     * the deadline ({@link System#nanoTime()}).
     *
     * @return true if all of it ended
     */
    boolean awaitEnd(long deadlineNanos) throws InterruptedException;

    /** Cancels the work still running and waits as {@link #awaitEnd} does. */
    void cancelRunning(long deadlineNanos) throws InterruptedException;

    /**
     * Drains all of {@code work} together: each stops accepting, all share one grace period, then
     * what still runs is cancelled and gets {@value #CANCEL_WAIT_MILLIS} ms more.
     *
     * @return true if everything ended within the grace period, false if some of it was cancelled
     */
    static boolean drain(List<? extends Drainable> work, long graceMillis) {
        work.forEach(Drainable::stopAccepting);
        try {
            long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(graceMillis);
            boolean ended = true;
            for (Drainable each : work) {
                ended &= each.awaitEnd(deadline);
            }
            if (!ended) {
                long cancelDeadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(CANCEL_WAIT_MILLIS);
                for (Drainable each : work) {
                    each.cancelRunning(cancelDeadline);
                }
            }
            return ended;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }
}

package studio.server.system;

/**
 * Work that the service lets finish on shutdown (see {@link GracefulShutdown}): it stops taking
 * more, then its work in hand ends or, after the grace period, is cancelled, within deadlines.
 */
public interface Drainable {

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
}

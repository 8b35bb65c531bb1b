package studio.server.job;

import java.util.Map;
import java.util.Set;
import java.util.concurrent.Executor;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

import studio.engine.render.RenderListener;
import studio.engine.render.RenderResult;
import studio.server.render.RenderBudget;
import studio.server.scene.compiling.CompiledScene;

/**
 * Where a job's tiles are rendered and who else sees the job. In a cluster of one ({@link #SINGLE},
 * every default here) the member that accepted a job renders it on its own pool and is the only one
 * that knows it. In a cluster (studio.server.cluster) the job's tiles are tasks every member pulls,
 * and its status, event log and image are in the cluster's maps, so that any member serves it and
 * another member takes it over ({@link Takeover}) when the one that accepted it dies. A job belongs to
 * the principal that submitted it ("" with sign-in off): to anyone else, the cluster knows no such job.
 */
public interface JobCluster {

    /** A cluster of one: nothing leaves this member. */
    JobCluster SINGLE = new JobCluster() {
    };

    /** What a member does to take over the job of a member that died. */
    @FunctionalInterface
    interface Takeover {
        /**
         * Runs the job here from now on.
         *
         * @param principal who submitted the job ("" with sign-in off)
         * @param scene     compiled from {@code sceneJson}, the JSON the job was accepted with
         */
        void resume(String id, String principal, CompiledScene scene, byte[] sceneJson);
    }

    /** Called once by the job service, which takes over jobs through {@code takeover}. */
    default void start(Takeover takeover) {
    }

    /**
     * Renders the job's tiles within the budget's time, calling the listener for each finished tile
     * (on the calling thread or a render thread, never holding a lock of the listener's).
     */
    default RenderResult render(String id, CompiledScene scene, RenderBudget budget, RenderListener listener,
                                BooleanSupplier cancelled) {
        return budget.render(scene.request().heardBy(listener).cancelledWhen(cancelled));
    }

    /**
     * A job of this member ran and is about to end: when this returns, every member serves its end
     * (and a done job's image, written before the end), so that the job reports its end only once any
     * member would; if the write failed, the cluster learns the end from the job's events instead.
     * Called on the job's thread, holding no lock; a bounded wait. Meanwhile the job serves its image.
     *
     * @param image the encoded image when {@code end} is done, else null
     */
    default void ending(String id, JobStatus end, byte[] image) {
    }

    /** The tiles each member has rendered for a job of this member, or null in a cluster of one. */
    default Map<String, Integer> workers(String id) {
        return null;
    }

    /**
     * A job was accepted (or taken over) here: the cluster learns of it before its id is answered.
     *
     * @param principal who submitted the job ("" with sign-in off): only they are served it
     * @param status  the job's status now
     * @param image   the job's image once it is done
     * @param resumed true for a job taken over from a member that died: its events so far were published
     * @return a listener that keeps the cluster told of the job's events, or null
     */
    default JobListener accepted(String id, String principal, byte[] sceneJson, Supplier<JobStatus> status, Supplier<byte[]> image,
                                 boolean resumed) {
        return null;
    }

    /** The status of a job another member runs, or null if the cluster knows no such job of {@code principal}'s. */
    default JobStatus status(String id, String principal) {
        return null;
    }

    /** The image of another member's job, or null if it has none (yet) or it is not {@code principal}'s. */
    default byte[] image(String id, String principal) {
        return null;
    }

    /**
     * Asks the member that runs the job to cancel it; its status, or null if the cluster knows no such job
     * of {@code principal}'s.
     */
    default JobStatus cancel(String id, String principal) {
        return null;
    }

    /**
     * Subscribes a listener to another member's job; its events are delivered through {@code sender}.
     *
     * @return false if the cluster knows no such job of {@code principal}'s
     */
    default boolean subscribe(String id, String principal, JobListener listener, Executor sender) {
        return false;
    }

    /**
     * A listener {@link #subscribe subscribed} to another member's job went away or left: its stream
     * stops. (The job goes on; its owner cancels it as abandoned once nobody has asked about it for
     * a while, as for a job whose own last listener left.)
     */
    default void unsubscribe(String id, JobListener listener) {
    }

    /** When anyone in the cluster last asked about the job (epoch millis), or 0 if not known. */
    default long lastSeenMillis(String id) {
        return 0;
    }

    /** True if the service, stopping, may hand its jobs to other members ({@link #handOver}): there are some. */
    default boolean canHandOver() {
        return false;
    }

    /**
     * The service is stopping: hands this member's unfinished jobs (running and queued) to the other
     * members, which go on with them from the tiles done, instead of letting them finish or cancelling
     * them here. From now on this member takes no tiles, and writes nothing more of these jobs to
     * the cluster (their renders here stop). Called once, when {@link #canHandOver} said yes.
     */
    default void handOver(Set<String> ids) {
    }

    /**
     * Waits until the jobs handed over have a new owner, at most until the deadline ({@link System#nanoTime()}).
     *
     * @return true if all have
     */
    default boolean awaitHandedOver(long deadlineNanos) throws InterruptedException {
        return true;
    }

    /** This member dropped a finished job: the cluster forgets it too. */
    default void dropped(String id) {
    }
}

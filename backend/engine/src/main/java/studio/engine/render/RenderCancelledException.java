package studio.engine.render;

/** Thrown by a render that was cancelled; tiles finished before are discarded with it. */
public final class RenderCancelledException extends RuntimeException {

    public RenderCancelledException() {
        super("render cancelled");
    }
}

package studio.server.render;

/** Every render slot is taken; the client should retry later. */
public final class RenderBusyException extends RuntimeException {

    public RenderBusyException() {
        super("the server is busy rendering other scenes; try again shortly");
    }
}

package studio.server.render;

/**
 * Every render slot, or the memory a render needs, is taken, the server is stopping, or it gave up
 * waiting for a render; the client should retry later.
 */
public final class RenderBusyException extends RuntimeException {

    public RenderBusyException() {
        this("the server is busy rendering other scenes; try again shortly");
    }

    public RenderBusyException(String message) {
        super(message);
    }
}

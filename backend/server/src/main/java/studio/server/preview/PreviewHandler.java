package studio.server.preview;

import java.io.IOException;
import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.SynchronousQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.springframework.web.ErrorResponseException;
import org.springframework.web.socket.BinaryMessage;
import org.springframework.web.socket.CloseStatus;
import org.springframework.web.socket.TextMessage;
import org.springframework.web.socket.WebSocketSession;
import org.springframework.web.socket.handler.AbstractWebSocketHandler;
import org.springframework.web.socket.handler.ConcurrentWebSocketSessionDecorator;

import studio.server.system.IntakeMemory;

/**
 * The WebSocket side of the live view ({@code /api/preview}): assembles each text message from the
 * container's pieces (its buffer stays at its default 8 KiB, allocated for every session; a message
 * may be as large as a request body, its memory reserved as it arrives), hands it to its session's {@link PreviewSession}, and
 * closes the session's work when the connection goes.
 */
final class PreviewHandler extends AbstractWebSocketHandler implements AutoCloseable {

    /** How long one frame may take to send, and how much may wait to be sent, before the view is closed. */
    static final int SEND_TIME_LIMIT_MILLIS = 10_000, SEND_BUFFER_LIMIT = 16 << 20;
    static final int WORKER_KEEP_ALIVE_SECONDS = 2;

    private static final String VIEW = "studio.preview.view", SOCKET = "studio.preview.socket",
            PARTS = "studio.preview.parts";

    private final PreviewRenderer renderer;
    private final long maxMessageBytes;
    private final ExecutorService workers;
    private final int maxSessions;
    private final Duration idleTimeout;
    /** Live views open or being opened (a place is taken at the handshake). */
    private final AtomicInteger open = new AtomicInteger();

    PreviewHandler(PreviewRenderer renderer, long maxMessageBytes, int maxSessions, Duration idleTimeout) {
        this.renderer = renderer;
        this.idleTimeout = idleTimeout;
        this.maxMessageBytes = maxMessageBytes;
        this.maxSessions = maxSessions;
        AtomicInteger count = new AtomicInteger();
        // a worker per view while it has a revision to show; idle workers end after a few seconds
        this.workers = new ThreadPoolExecutor(0, Integer.MAX_VALUE, WORKER_KEEP_ALIVE_SECONDS, TimeUnit.SECONDS,
                new SynchronousQueue<>(), r -> {
                    Thread t = new Thread(r, "live-view-" + count.incrementAndGet());
                    t.setDaemon(true);
                    return t;
                });
    }

    /** Live views open now. */
    int open() {
        return open.get();
    }

    /** Takes a place for a new view; false when all are taken. */
    boolean tryOpen() {
        if (open.incrementAndGet() > maxSessions) {
            open.decrementAndGet();
            return false;
        }
        return true;
    }

    /** Gives a view's place back. */
    void release() {
        open.decrementAndGet();
    }

    @Override
    public void afterConnectionEstablished(WebSocketSession session) {
        if (session instanceof org.springframework.web.socket.adapter.NativeWebSocketSession adapter
                && adapter.getNativeSession() instanceof jakarta.websocket.Session container) {
            container.setMaxIdleTimeout(idleTimeout.toMillis());
        }
        WebSocketSession socket = new ConcurrentWebSocketSessionDecorator(session, SEND_TIME_LIMIT_MILLIS,
                SEND_BUFFER_LIMIT);
        session.getAttributes().put(SOCKET, socket);
        session.getAttributes().put(VIEW, new PreviewSession(renderer, workers, new PreviewSession.Output() {
            @Override
            public void frame(byte[] message) throws IOException {
                socket.sendMessage(new BinaryMessage(message));
            }

            @Override
            public void text(String message) throws IOException {
                socket.sendMessage(new TextMessage(message));
            }

            @Override
            public void close() {
                try {
                    socket.close(CloseStatus.SERVER_ERROR.withReason("the live view could not go on"));
                } catch (IOException e) {
                    // gone already
                }
            }
        }, maxMessageBytes));
    }

    @Override
    protected void handleTextMessage(WebSocketSession session, TextMessage message) throws IOException {
        PreviewSession view = view(session);
        if (view == null) {
            return; // a piece the container delivers after the view was closed (for a message too large, say)
        }
        Parts parts = (Parts) session.getAttributes().computeIfAbsent(PARTS, k -> new Parts());
        String piece = parts.carried(message.getPayload(), message.isLast());
        parts.length += piece.length();
        if (parts.length > maxMessageBytes) {
            parts.clear();
            close(session);
            session.close(CloseStatus.TOO_BIG_TO_PROCESS.withReason("a message may be at most " + maxMessageBytes
                    + " bytes (studio.limits.max-body-bytes)"));
            return;
        }
        if (parts.refusal == null) {
            if (parts.memory == null) {
                parts.memory = IntakeMemory.of(renderer.memory());
                view.arriving();
            }
            byte[] bytes = piece.getBytes(StandardCharsets.UTF_8);
            try {
                parts.memory.bodyArrived(bytes, 0, bytes.length); // what these bytes take once read, before keeping them
                parts.bytes.writeBytes(bytes);
            } catch (ErrorResponseException e) {
                parts.refuse(e);
            }
        }
        if (message.isLast()) {
            if (parts.refusal != null) {
                view.notArriving();
                socket(session).sendMessage(new TextMessage(renderer.problem(null, parts.refusal)));
            } else {
                view.receive(parts.bytes.toByteArray(), parts.memory); // the view owns the memory now
                parts.memory = null;
            }
            parts.clear();
        }
    }

    @Override
    protected void handleBinaryMessage(WebSocketSession session, BinaryMessage message) throws IOException {
        session.close(CloseStatus.NOT_ACCEPTABLE.withReason("the live view takes text messages (JSON)"));
    }

    @Override
    public boolean supportsPartialMessages() {
        return true;
    }

    @Override
    public void afterConnectionClosed(WebSocketSession session, CloseStatus status) {
        close(session);
    }

    /** Ends the view's work and gives its place back, once, whoever closes it first. */
    private void close(WebSocketSession session) {
        PreviewSession view = (PreviewSession) session.getAttributes().remove(VIEW);
        if (view != null) {
            view.close();
            release();
        }
        Parts parts = (Parts) session.getAttributes().remove(PARTS);
        if (parts != null) {
            parts.clear();
        }
    }

    private static WebSocketSession socket(WebSocketSession session) {
        return (WebSocketSession) session.getAttributes().get(SOCKET);
    }

    private static PreviewSession view(WebSocketSession session) {
        return (PreviewSession) session.getAttributes().get(VIEW);
    }

    @Override
    public void close() {
        workers.shutdownNow();
    }

    /**
     * A text message being assembled as UTF-8, and the memory its reading holds (reserved by the
     * bytes' shape as they arrive, as a request body's: see {@link IntakeMemory#bodyArrived}).
     */
    private static final class Parts {
        final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        IntakeMemory memory;
        /** Characters received, kept or not. */
        long length;
        /** A high surrogate that ended a piece: its pair begins the next one. */
        String carry = "";
        /** Why the rest of this message is dropped (its memory was refused); the client is told. */
        ErrorResponseException refusal;

        /** The piece, with a split surrogate pair made whole across pieces. */
        String carried(String piece, boolean last) {
            String whole = carry + piece;
            carry = "";
            if (!last && !whole.isEmpty() && Character.isHighSurrogate(whole.charAt(whole.length() - 1))) {
                carry = whole.substring(whole.length() - 1);
                whole = whole.substring(0, whole.length() - 1);
            }
            return whole;
        }

        void refuse(ErrorResponseException e) {
            long seen = length;
            clear();
            length = seen;
            refusal = e;
        }

        void clear() {
            bytes.reset();
            if (memory != null) {
                memory.close();
                memory = null;
            }
            length = 0;
            carry = "";
            refusal = null;
        }
    }
}

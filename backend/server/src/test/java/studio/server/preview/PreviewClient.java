package studio.server.preview;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.nio.ByteBuffer;
import java.util.List;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/** A live-view client for tests: sends revisions, keeps every frame and problem it receives, in order. */
final class PreviewClient implements WebSocket.Listener, AutoCloseable {

    static final JsonMapper JSON = JsonMapper.builder().build();

    /** A received frame: its header and the encoded image. */
    record Frame(JsonNode header, byte[] image) {
        long revision() {
            return header.get("revision").asLong();
        }

        boolean last() {
            return header.get("final").asBoolean();
        }
    }

    final List<Frame> frames = new CopyOnWriteArrayList<>();
    final List<JsonNode> texts = new CopyOnWriteArrayList<>();
    /** Frames and texts in the order they came: "frame:REV:PASS" or "text:REV". */
    final List<String> order = new CopyOnWriteArrayList<>();
    volatile Integer closedWith;
    private final WebSocket socket;
    private final ByteArrayOutputStream binary = new ByteArrayOutputStream();
    private final StringBuilder text = new StringBuilder();

    PreviewClient(int port) throws Exception {
        socket = HttpClient.newHttpClient().newWebSocketBuilder()
                .buildAsync(URI.create("ws://localhost:" + port + "/api/preview"), this).get(10, TimeUnit.SECONDS);
    }

    void send(long revision, String scene, int width, int height) throws Exception {
        send("{\"revision\": " + revision + ", \"width\": " + width + ", \"height\": " + height + ", \"scene\": " + scene
                + "}");
    }

    /** A patch (a JSON array of RFC 6902 operations) to revision {@code base}'s scene, as revision {@code revision}. */
    void sendPatch(long revision, long base, String patch, int width, int height) throws Exception {
        send("{\"revision\": " + revision + ", \"base\": " + base + ", \"width\": " + width + ", \"height\": " + height
                + ", \"patch\": " + patch + "}");
    }

    void send(String message) throws Exception {
        socket.sendText(message, true).get(30, TimeUnit.SECONDS);
    }

    /** A piece of a message: the message goes on with the next piece, and ends with one that is {@code last}. */
    void sendPiece(String piece, boolean last) throws Exception {
        socket.sendText(piece, last).get(30, TimeUnit.SECONDS);
    }

    Frame lastFrame() {
        return frames.isEmpty() ? null : frames.get(frames.size() - 1);
    }

    @Override
    public CompletionStage<?> onBinary(WebSocket webSocket, ByteBuffer data, boolean last) {
        byte[] bytes = new byte[data.remaining()];
        data.get(bytes);
        binary.writeBytes(bytes);
        if (last) {
            byte[] message = binary.toByteArray();
            binary.reset();
            int length = ByteBuffer.wrap(message, 0, 4).getInt();
            JsonNode header = JSON.readTree(new ByteArrayInputStream(message, 4, length));
            byte[] image = java.util.Arrays.copyOfRange(message, 4 + length, message.length);
            frames.add(new Frame(header, image));
            order.add("frame:" + header.get("revision").asLong() + ":" + header.get("pass").asInt());
        }
        webSocket.request(1);
        return null;
    }

    @Override
    public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
        text.append(data);
        if (last) {
            JsonNode message = JSON.readTree(text.toString());
            text.setLength(0);
            texts.add(message);
            order.add("text:" + message.get("revision"));
        }
        webSocket.request(1);
        return null;
    }

    @Override
    public CompletionStage<?> onClose(WebSocket webSocket, int statusCode, String reason) {
        closedWith = statusCode;
        return null;
    }

    @Override
    public void close() {
        socket.sendClose(WebSocket.NORMAL_CLOSURE, "done").orTimeout(5, TimeUnit.SECONDS).exceptionally(e -> null);
        socket.abort();
    }

}

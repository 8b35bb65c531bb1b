package studio.server.preview;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;

/**
 * One frame of the live view as it goes over the WebSocket: a 4-byte big-endian length, that many
 * bytes of UTF-8 JSON header, then the encoded image.
 *
 * @param format "jpeg" for the passes before the last, "png" for the last
 * @param millis the server's time from receiving the revision to sending this frame
 */
record PreviewFrame(long revision, int pass, int width, int height, int samplesPerPixel, boolean last,
                    String format, long millis) {

    /** The header's JSON (its fields are numbers, booleans and a fixed word: nothing to escape). */
    String headerJson() {
        return "{\"revision\":" + revision + ",\"pass\":" + pass + ",\"width\":" + width + ",\"height\":" + height
                + ",\"samplesPerPixel\":" + samplesPerPixel + ",\"final\":" + last + ",\"format\":\"" + format
                + "\",\"millis\":" + millis + "}";
    }

    /** The message: length, header, image. */
    byte[] encode(byte[] image) {
        byte[] header = headerJson().getBytes(StandardCharsets.UTF_8);
        ByteArrayOutputStream out = new ByteArrayOutputStream(4 + header.length + image.length);
        out.write(header.length >>> 24);
        out.write(header.length >>> 16);
        out.write(header.length >>> 8);
        out.write(header.length);
        out.writeBytes(header);
        out.writeBytes(image);
        return out.toByteArray();
    }
}

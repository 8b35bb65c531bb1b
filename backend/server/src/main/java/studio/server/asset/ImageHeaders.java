package studio.server.asset;

import java.util.Arrays;

/**
 * An image's width and height from its header alone: a PNG's IHDR chunk, a JPEG's first
 * start-of-frame segment. Nothing is decoded, so an image that declares 100,000 x 100,000 pixels
 * costs the few bytes read here.
 */
final class ImageHeaders {

    /** Width and height in pixels, as the header declares them. */
    record Size(long width, long height) {
        long pixels() {
            return width * height;
        }
    }

    private static final byte[] IHDR = {'I', 'H', 'D', 'R'};

    private ImageHeaders() {
    }

    /** @throws IllegalArgumentException saying what is wrong with the header */
    static Size png(byte[] b) {
        // signature (8), IHDR's length (4) and type (4), width (4), height (4), depth, colour, compression,
        // filter, interlace (5), CRC (4)
        if (b.length < 33) {
            throw new IllegalArgumentException("it ends before its IHDR header (" + b.length + " bytes)");
        }
        if (Bytes.bigEndianInt(b, 8) != 13 || !Arrays.equals(b, 12, 16, IHDR, 0, 4)) {
            throw new IllegalArgumentException("its first chunk is not a 13-byte IHDR");
        }
        long width = Bytes.bigEndianInt(b, 16) & 0xffffffffL;
        long height = Bytes.bigEndianInt(b, 20) & 0xffffffffL;
        if (width == 0 || height == 0 || width > Integer.MAX_VALUE || height > Integer.MAX_VALUE) {
            throw new IllegalArgumentException("its IHDR declares " + width + " x " + height + " pixels");
        }
        return new Size(width, height);
    }

    /** @throws IllegalArgumentException saying what is wrong with the segments before the first frame */
    static Size jpeg(byte[] b) {
        int at = 2; // after SOI
        while (true) {
            if (at + 4 > b.length) {
                throw new IllegalArgumentException("it ends before its frame header (SOF)");
            }
            if ((b[at] & 0xff) != 0xff) {
                throw new IllegalArgumentException("no segment marker at byte " + at);
            }
            int marker = b[at + 1] & 0xff;
            if (marker == 0xff) { // fill byte
                at++;
                continue;
            }
            if (marker == 0x01 || marker >= 0xd0 && marker <= 0xd7) { // no length
                at += 2;
                continue;
            }
            if (marker == 0xda || marker == 0xd9) {
                throw new IllegalArgumentException("its scan (or end) comes before its frame header (SOF)");
            }
            int length = Bytes.bigEndianShort(b, at + 2);
            if (length < 2 || at + 2 + length > b.length) {
                throw new IllegalArgumentException("its segment at byte " + at + " runs past the end");
            }
            boolean frame = marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc;
            if (frame) {
                if (length < 8) {
                    throw new IllegalArgumentException("its frame header (SOF) is too short");
                }
                long height = Bytes.bigEndianShort(b, at + 5);
                long width = Bytes.bigEndianShort(b, at + 7);
                if (width == 0 || height == 0) {
                    throw new IllegalArgumentException("its frame header declares " + width + " x " + height
                            + " pixels");
                }
                return new Size(width, height);
            }
            at += 2 + length;
        }
    }
}

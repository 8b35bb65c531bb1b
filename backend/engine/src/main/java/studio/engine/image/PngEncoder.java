package studio.engine.image;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.stream.IntStream;
import java.util.zip.Adler32;
import java.util.zip.CRC32;
import java.util.zip.Deflater;

/**
 * Writes 8-bit RGB pixels as a PNG, on all cores. Each row takes the filter whose output has the
 * smallest sum of absolute values (libpng's heuristic); bands of rows are deflated in parallel,
 * each band primed with the 32 KiB before it as its dictionary and ended on a byte boundary by a
 * sync flush, and the pieces joined into one zlib stream (as pigz does), so the file is one
 * ordinary PNG. The bands depend only on the image's size: the same pixels give the same bytes on
 * any number of cores. The file says its pixels are sRGB (an sRGB chunk).
 */
final class PngEncoder {

    private static final byte[] SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    /** Rows are deflated in bands of about this many bytes; smaller images in one piece. */
    private static final int BAND_BYTES = 1 << 20;
    private static final int WINDOW = 32 * 1024;
    private static final int COST_STRIDE = 7;
    /**
     * Rows are unpacked, costed and filtered in runs of this many bytes (whole pixels, and a
     * multiple of the cost stride), each a call of its own: {@code bin/studio}'s render JVM has no
     * on-stack replacement, so a loop over a whole row runs interpreted until its method has been
     * called a hundred times or more. Filtering 800x600 at the end of a render took 30-35 ms with
     * whole rows, 12-14 ms in runs.
     */
    private static final int RUN_BYTES = 3 * COST_STRIDE * 16;
    /**
     * zlib's level 4: a 4096x4096 render-like image in about a third of the default level 6's time,
     * for an eighth more bytes (and in half of ImageIO's writer's time, for 0.6 of its bytes).
     */
    private static final int LEVEL = 4;

    private PngEncoder() {
    }

    /** @param rgb one int per pixel, 0xRRGGBB, row-major from the top left */
    static void write(int[] rgb, int width, int height, OutputStream out) throws IOException {
        if (width <= 0 || height <= 0 || rgb.length < (long) width * height) {
            throw new IllegalArgumentException("no " + width + "x" + height + " image in " + rgb.length + " pixels");
        }
        int stride = 1 + 3 * width;
        byte[] filtered = new byte[Math.multiplyExact(stride, height)];
        IntStream rows = IntStream.range(0, height);
        (filtered.length >= BAND_BYTES ? rows.parallel() : rows).forEach(y -> filterRow(rgb, width, y, filtered));

        int rowsPerBand = Math.max(1, BAND_BYTES / stride);
        int bands = (height + rowsPerBand - 1) / rowsPerBand;
        byte[][] pieces = new byte[bands][];
        IntStream.range(0, bands).parallel().forEach(band -> {
            int from = band * rowsPerBand * stride;
            int to = Math.min(height, (band + 1) * rowsPerBand) * stride;
            pieces[band] = deflate(filtered, from, to, band == bands - 1);
        });
        Adler32 adler = new Adler32();
        adler.update(filtered);

        DataOutputStream data = new DataOutputStream(out);
        data.write(SIGNATURE);
        ByteArrayOutputStream header = new ByteArrayOutputStream(13);
        DataOutputStream h = new DataOutputStream(header);
        h.writeInt(width);
        h.writeInt(height);
        h.write(new byte[] {8, 2, 0, 0, 0}); // 8 bits, RGB, deflate, adaptive filters, no interlace
        chunk(data, "IHDR", header.toByteArray());
        chunk(data, "sRGB", new byte[] {0}); // perceptual rendering intent
        chunk(data, "IDAT", new byte[] {0x78, (byte) 0x9c}); // zlib header: deflate, 32 KiB window
        for (byte[] piece : pieces) {
            chunk(data, "IDAT", piece);
        }
        long sum = adler.getValue();
        chunk(data, "IDAT", new byte[] {(byte) (sum >>> 24), (byte) (sum >>> 16), (byte) (sum >>> 8), (byte) sum});
        chunk(data, "IEND", new byte[0]);
        data.flush();
    }

    /** Row y as its filter type byte and filtered bytes, with the filter that leaves the least to code. */
    private static void filterRow(int[] rgb, int width, int y, byte[] filtered) {
        int n = 3 * width;
        byte[] row = new byte[n], above = new byte[n];
        unpack(rgb, width, y, row);
        if (y > 0) {
            unpack(rgb, width, y - 1, above);
        }
        // the cost of a filter: the sum of its output bytes' magnitudes, taken as signed, over every
        // seventh byte (all three channels take turns): the choice is nearly always the same as over
        // every byte, for a seventh of the work
        long[] costs = new long[5];
        for (int from = 0; from < n; from += RUN_BYTES) {
            addCosts(row, above, from, Math.min(n, from + RUN_BYTES), costs);
        }
        long none = costs[0], sub = costs[1], up = costs[2], average = costs[3], paeth = costs[4];
        long least = Math.min(Math.min(none, sub), Math.min(Math.min(up, average), paeth));
        int filter = least == paeth ? 4 : least == sub ? 1 : least == up ? 2 : least == average ? 3 : 0;
        int at = y * (1 + n);
        filtered[at++] = (byte) filter;
        for (int from = 0; from < n; from += RUN_BYTES) {
            applyFilter(filter, row, above, from, Math.min(n, from + RUN_BYTES), filtered, at);
        }
    }

    /** Adds the costs of the five filters over bytes [from, to) of a row (from a multiple of the stride). */
    private static void addCosts(byte[] row, byte[] above, int from, int to, long[] costs) {
        long none = 0, sub = 0, up = 0, average = 0, paeth = 0;
        for (int i = from; i < to; i += COST_STRIDE) {
            int x = row[i] & 0xff, a = i >= 3 ? row[i - 3] & 0xff : 0, b = above[i] & 0xff;
            int c = i >= 3 ? above[i - 3] & 0xff : 0;
            none += magnitude(x);
            sub += magnitude(x - a);
            up += magnitude(x - b);
            average += magnitude(x - ((a + b) >>> 1));
            paeth += magnitude(x - paeth(a, b, c));
        }
        costs[0] += none;
        costs[1] += sub;
        costs[2] += up;
        costs[3] += average;
        costs[4] += paeth;
    }

    /** Bytes [from, to) of a row through the filter, into out from {@code at + from}. */
    private static void applyFilter(int filter, byte[] row, byte[] above, int from, int to, byte[] out, int at) {
        for (int i = from; i < to; i++) {
            int x = row[i] & 0xff, a = i >= 3 ? row[i - 3] & 0xff : 0, b = above[i] & 0xff;
            out[at + i] = (byte) switch (filter) {
                case 0 -> x;
                case 1 -> x - a;
                case 2 -> x - b;
                case 3 -> x - ((a + b) >>> 1);
                default -> x - paeth(a, b, i >= 3 ? above[i - 3] & 0xff : 0);
            };
        }
    }

    /** |v| of a difference taken as a signed byte. */
    private static int magnitude(int difference) {
        int v = (byte) difference;
        return v < 0 ? -v : v;
    }

    private static void unpack(int[] rgb, int width, int y, byte[] row) {
        for (int x = 0; x < width; x += RUN_BYTES / 3) {
            unpack(rgb, y * width + x, Math.min(RUN_BYTES / 3, width - x), row, 3 * x);
        }
    }

    /** {@code count} pixels from rgb[from] as bytes into row[at ..]. */
    private static void unpack(int[] rgb, int from, int count, byte[] row, int at) {
        for (int i = 0; i < count; i++) {
            int p = rgb[from + i];
            row[at + 3 * i] = (byte) (p >>> 16);
            row[at + 3 * i + 1] = (byte) (p >>> 8);
            row[at + 3 * i + 2] = (byte) p;
        }
    }

    private static int paeth(int a, int b, int c) {
        int p = a + b - c;
        int pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
        return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
    }

    /** Raw deflate of data[from, to), primed with the window before it; the last piece ends the stream. */
    private static byte[] deflate(byte[] data, int from, int to, boolean last) {
        Deflater deflater = new Deflater(LEVEL, true);
        try {
            if (from > 0) {
                int start = Math.max(0, from - WINDOW);
                deflater.setDictionary(data, start, from - start);
            }
            deflater.setInput(data, from, to - from);
            ByteArrayOutputStream piece = new ByteArrayOutputStream((to - from) / 2 + 64);
            byte[] buffer = new byte[64 * 1024];
            if (last) {
                deflater.finish();
                while (!deflater.finished()) {
                    piece.write(buffer, 0, deflater.deflate(buffer));
                }
            } else {
                int written;
                do {
                    written = deflater.deflate(buffer, 0, buffer.length, Deflater.SYNC_FLUSH);
                    piece.write(buffer, 0, written);
                } while (written == buffer.length);
            }
            return piece.toByteArray();
        } finally {
            deflater.end();
        }
    }

    private static void chunk(DataOutputStream out, String type, byte[] body) throws IOException {
        byte[] name = type.getBytes(StandardCharsets.US_ASCII);
        CRC32 crc = new CRC32();
        crc.update(name);
        crc.update(body);
        out.writeInt(body.length);
        out.write(name);
        out.write(body);
        out.writeInt((int) crc.getValue());
    }
}

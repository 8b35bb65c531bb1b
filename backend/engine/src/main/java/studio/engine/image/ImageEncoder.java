package studio.engine.image;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferByte;
import java.awt.image.DataBufferInt;
import java.io.IOException;
import java.io.OutputStream;
import java.util.Iterator;
import java.util.stream.IntStream;

import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

import studio.engine.math.Srgb;
import studio.engine.render.Film;
import studio.engine.render.PixelLattice;
import studio.engine.render.TileRect;

/** Encodes a linear-light film as an 8-bit sRGB PNG or JPEG: the only place sRGB encoding happens. */
public final class ImageEncoder {

    /** Images of at least this many pixels are converted by several threads. */
    private static final long PARALLEL_PIXELS = 1 << 18;
    /**
     * Rows are converted in runs of this many pixels, each a call of its own: {@code bin/studio}'s
     * render JVM has no on-stack replacement, so a loop over a whole row runs interpreted until its
     * method has been called a hundred times or more (as {@code PngEncoder}'s runs).
     */
    private static final int RUN = 32;

    private ImageEncoder() {
    }

    /** The film as 8-bit sRGB, values clamped to [0, 1]. */
    public static BufferedImage toImage(Film film) {
        return toImage(film, new TileRect(0, 0, film.width(), film.height()));
    }

    /** A rectangle of the film (a finished tile, say) as 8-bit sRGB. */
    public static BufferedImage toImage(Film film, TileRect region) {
        int w = region.width(), h = region.height();
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        int[] pixels = ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
        IntStream rows = IntStream.range(0, h);
        // large images convert their rows on all cores (about 0.1 s for 4096 x 4096 instead of 1.7 s)
        (w * (long) h >= PARALLEL_PIXELS ? rows.parallel() : rows).forEach(y -> {
            for (int x = 0; x < w; x += RUN) {
                pack(film, region.x() + x, region.y() + y, 1, Math.min(RUN, w - x), pixels, y * w + x);
            }
        });
        return image;
    }

    /**
     * The film's pixels on a lattice as an image of their own, {@code lattice.count(width)} x
     * {@code lattice.count(height)}: pixel (i, j) is the film's (offset + i step, offset + j step).
     */
    public static BufferedImage toImage(Film film, PixelLattice lattice) {
        int step = lattice.step(), offset = lattice.offset();
        int w = lattice.count(film.width()), h = lattice.count(film.height());
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        int[] pixels = ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
        IntStream rows = IntStream.range(0, h);
        (w * (long) h >= PARALLEL_PIXELS ? rows.parallel() : rows).forEach(y -> {
            for (int x = 0; x < w; x += RUN) {
                pack(film, offset + x * step, offset + y * step, step, Math.min(RUN, w - x), pixels, y * w + x);
            }
        });
        return image;
    }

    /**
     * As {@link #toImage(Film, PixelLattice)}, the same pixels laid out as blue, green, red bytes
     * ({@code TYPE_3BYTE_BGR}), which ImageIO's JPEG writer takes as they are: the same file
     * ({@code ImageEncoderTest}) without the writer converting packed ints row by row (a 640x480
     * frame in about 2.8 ms of CPU instead of 4.6). Every JPEG the service writes goes this way.
     */
    public static BufferedImage toJpegImage(Film film, PixelLattice lattice) {
        int step = lattice.step(), offset = lattice.offset();
        int w = lattice.count(film.width()), h = lattice.count(film.height());
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_3BYTE_BGR);
        byte[] bytes = ((DataBufferByte) image.getRaster().getDataBuffer()).getData();
        IntStream rows = IntStream.range(0, h);
        (w * (long) h >= PARALLEL_PIXELS ? rows.parallel() : rows).forEach(y -> {
            for (int x = 0; x < w; x += RUN) {
                packBgr(film, offset + x * step, offset + y * step, step, Math.min(RUN, w - x), bytes, 3 * (y * w + x));
            }
        });
        return image;
    }

    /** As {@link #pack}, into bytes[at ..] as blue, green, red. */
    private static void packBgr(Film film, int fx, int fy, int step, int count, byte[] bytes, int at) {
        for (int i = 0, x = fx, o = at; i < count; i++, x += step, o += 3) {
            bytes[o] = (byte) Srgb.toByte(film.get(x, fy, 2));
            bytes[o + 1] = (byte) Srgb.toByte(film.get(x, fy, 1));
            bytes[o + 2] = (byte) Srgb.toByte(film.get(x, fy, 0));
        }
    }

    /** {@code count} pixels of the film's row fy, from fx on every {@code step}th, as 8-bit sRGB, into pixels[at ..]. */
    private static void pack(Film film, int fx, int fy, int step, int count, int[] pixels, int at) {
        for (int i = 0, x = fx; i < count; i++, x += step) {
            pixels[at + i] = Srgb.toByte(film.get(x, fy, 0)) << 16 | Srgb.toByte(film.get(x, fy, 1)) << 8
                    | Srgb.toByte(film.get(x, fy, 2));
        }
    }

    public static void writePng(BufferedImage image, OutputStream out) throws IOException {
        int[] rgb = image.getType() == BufferedImage.TYPE_INT_RGB
                ? ((DataBufferInt) image.getRaster().getDataBuffer()).getData()
                : image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
        PngEncoder.write(rgb, image.getWidth(), image.getHeight(), out);
    }

    /** Writes a baseline JPEG; {@code quality} from 0 (smallest) to 1 (best). */
    public static void writeJpeg(BufferedImage image, double quality, OutputStream out) throws IOException {
        if (!(quality >= 0 && quality <= 1)) {
            throw new IllegalArgumentException("JPEG quality must be in [0, 1]: " + quality);
        }
        Iterator<ImageWriter> writers = ImageIO.getImageWritersByFormatName("jpeg");
        if (!writers.hasNext()) {
            throw new IOException("no JPEG writer available");
        }
        ImageWriter writer = writers.next();
        // in memory: ImageIO's default stream caches in a temporary file, a file per frame of the live view
        try (ImageOutputStream stream = new MemoryCacheImageOutputStream(out)) {
            writer.setOutput(stream);
            ImageWriteParam param = writer.getDefaultWriteParam();
            param.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
            param.setCompressionQuality((float) quality);
            writer.write(null, new IIOImage(image, null, null), param);
        } finally {
            writer.dispose();
        }
    }
}

package studio.server.render;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;

import studio.engine.image.ImageEncoder;
import studio.engine.render.Film;
import studio.engine.render.PixelLattice;

/** Encodes a film in the format a scene asks for. */
public final class ImageFiles {

    private ImageFiles() {
    }

    public static void write(Film film, String format, double quality, OutputStream out) throws IOException {
        if (format.equals("jpg")) {
            // blue-green-red bytes, which the JPEG writer takes as they are: the same file as from packed ints
            ImageEncoder.writeJpeg(ImageEncoder.toJpegImage(film, PixelLattice.ALL), quality, out);
        } else {
            ImageEncoder.writePng(ImageEncoder.toImage(film), out);
        }
    }

    public static byte[] encode(Film film, String format, double quality) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            write(film, format, quality, out);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return out.toByteArray();
    }
}

package studio.server.job;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.Base64;

import studio.engine.image.ImageEncoder;
import studio.engine.render.Film;
import studio.engine.render.TileRect;

/** A finished tile as a job's events carry it: a base64 PNG, written by the same encoder as whole images. */
public final class TilePng {

    private TilePng() {
    }

    public static String encode(Film film, TileRect tile) {
        var pixels = ImageEncoder.toImage(film, tile);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            ImageEncoder.writePng(pixels, out);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return Base64.getEncoder().encodeToString(out.toByteArray());
    }
}

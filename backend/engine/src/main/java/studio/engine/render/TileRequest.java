package studio.engine.render;

import java.util.Objects;

/**
 * What one tile task asks of a {@link TileRenderer}: the tile's rectangle, which of its pixels,
 * the film they go into and the rays they record. The worker's scene, settings and stop signal are
 * its own; callers differ by data ({@link #whole} for a whole tile, {@link RenderRequest#tile} for
 * a tile of a render).
 *
 * @param film   the film the pixels go into (an image's, or the tile's own: {@link Film#ofTile}); its
 *               other pixels are left as they are
 * @param tile   the tile's rectangle
 * @param pixels the tile's pixels to render ({@link PixelLattice#ALL}: every one)
 * @param except pixels of {@code pixels} left as the film has them (null: none)
 * @param paths  pixels the film holds whose rays a change did not touch, left out, and where the rays
 *               of the pixels rendered are recorded (null: none; fixed sampling only, see {@link PixelPaths})
 */
public record TileRequest(Film film, TileRect tile, PixelLattice pixels, PixelLattice except, PixelPaths paths) {

    public TileRequest {
        Objects.requireNonNull(film, "film");
        Objects.requireNonNull(tile, "tile");
        Objects.requireNonNull(pixels, "pixels");
    }

    /** Every pixel of the tile into the film, recording nothing. */
    public static TileRequest whole(Film film, TileRect tile) {
        return new TileRequest(film, tile, PixelLattice.ALL, null, null);
    }
}

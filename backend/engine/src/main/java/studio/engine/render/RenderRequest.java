package studio.engine.render;

import java.util.Objects;
import java.util.function.BooleanSupplier;

import studio.engine.scene.Scene;

/**
 * What one render is asked to do: the scene with its settings, the film it fills and which of its
 * pixels, the rays it records, who hears each tile and what cancels it. Callers differ by data, not
 * by overloads: {@link #of} is a whole render into a new film, and the withers change one part.
 *
 * @param film      the film the render fills; the settings' size
 * @param pixels    the pixels to render ({@link PixelLattice#ALL}: every one)
 * @param except    pixels of {@code pixels} left as the film has them (null: none)
 * @param paths     pixels the film holds from an earlier render whose rays a change did not touch, and
 *                  where the rays of the pixels rendered are recorded (null: none; see {@link PixelPaths})
 * @param listener  hears each finished tile
 * @param cancelled asked before each tile and while tiles render (see {@link Renderer#render})
 */
public record RenderRequest(Scene scene, RenderSettings settings, Film film, PixelLattice pixels, PixelLattice except,
                            PixelPaths paths, RenderListener listener, BooleanSupplier cancelled) {

    public RenderRequest {
        Objects.requireNonNull(scene, "scene");
        Objects.requireNonNull(settings, "settings");
        Objects.requireNonNull(film, "film");
        Objects.requireNonNull(pixels, "pixels");
        Objects.requireNonNull(listener, "listener");
        Objects.requireNonNull(cancelled, "cancelled");
    }

    /** The whole image into a new film of the settings' size, heard by nobody, never cancelled. */
    public static RenderRequest of(Scene scene, RenderSettings settings) {
        return new RenderRequest(scene, settings, new Film(settings.width(), settings.height()), PixelLattice.ALL,
                null, null, RenderListener.NONE, () -> false);
    }

    /** The same render, heard by {@code to}. */
    public RenderRequest heardBy(RenderListener to) {
        return new RenderRequest(scene, settings, film, pixels, except, paths, to, cancelled);
    }

    /** The same render, cancelled once {@code when} answers true. */
    public RenderRequest cancelledWhen(BooleanSupplier when) {
        return new RenderRequest(scene, settings, film, pixels, except, paths, listener, when);
    }

    /** The same render into {@code into}, only the pixels of {@code only} that are not on {@code but} (null: none). */
    public RenderRequest into(Film into, PixelLattice only, PixelLattice but) {
        return new RenderRequest(scene, settings, into, only, but, paths, listener, cancelled);
    }

    /** This render's part in {@code tile}: its film, pixels and recorded rays there. */
    public TileRequest tile(TileRect tile) {
        return new TileRequest(film, tile, pixels, except, paths);
    }

    /** The same render, leaving out the pixels {@code known} holds and recording the rays of the others there. */
    public RenderRequest recording(PixelPaths known) {
        return new RenderRequest(scene, settings, film, pixels, except, known, listener, cancelled);
    }
}

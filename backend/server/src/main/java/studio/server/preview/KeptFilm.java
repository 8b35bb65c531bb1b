package studio.server.preview;

import java.util.List;
import java.util.concurrent.atomic.AtomicReference;

import studio.engine.geometry.Shape;
import studio.engine.render.Film;
import studio.engine.render.PixelPaths;
import studio.engine.render.RenderSettings;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneEdit;
import studio.server.render.RenderMemory;
import studio.server.system.MemoryBudget;

/**
 * A live view's one-sample film, kept from one revision to the next with where each pixel's rays
 * went ({@link PixelPaths}), so that an edit renders again only the pixels it can reach: a moved
 * object, its shadows and what reflects it. The next revision's one-sample passes render into it,
 * leaving out the pixels still known. Which objects the edit changed is told by the revision's
 * reading ({@link SceneReuse}: from a patch's paths, or the elements of a whole scene that differ),
 * not worked out again ({@link SceneEdit}); another camera, light, view size or object count, or
 * an edit not told, forgets every pixel.
 *
 * <p>Holds the film, the paths and the last scene in the render memory while the view is open
 * (24 + {@value PixelPaths#BYTES_PER_PIXEL} bytes a pixel, and the scene's objects), as a
 * yielding reservation: other work that finds the memory short takes it back, and the next
 * revision renders every pixel. When the memory cannot hold them, the passes render into a film
 * of their own, as without it. Used by the view's worker, one revision at a time; {@link #drop}
 * and {@link #close} by any thread, at once.
 */
final class KeptFilm implements AutoCloseable {

    /** Bytes a pixel: the film's three doubles and the paths'. */
    static final long BYTES_PER_PIXEL = 24 + PixelPaths.BYTES_PER_PIXEL;

    /** The film and paths for one revision's one-sample passes, the settings and scene they are of, and their memory. */
    record Kept(RenderSettings settings, Film film, PixelPaths paths, Scene scene, MemoryBudget.Reservation memory) {
    }

    private final MemoryBudget memory;
    private final AtomicReference<Kept> kept = new AtomicReference<>();
    private volatile boolean closed;

    KeptFilm(MemoryBudget memory) {
        this.memory = memory;
    }

    /**
     * The film and paths for a revision's one-sample passes of {@code scene} at {@code oneSample}:
     * the kept ones with every pixel the edit since the last revision can reach forgotten, or new
     * ones; null if the memory cannot hold them (the passes then need a film of their own).
     *
     * @param origins for each object of {@code scene}, the index of the last revision's object it is
     *                unchanged from, or -1; null if not known (every pixel is forgotten)
     */
    Kept prepare(Scene scene, RenderSettings oneSample, int[] origins) {
        Kept last = kept.getAndSet(null);
        Kept next;
        if (last != null && last.settings().equals(oneSample)) {
            last.memory().close();
            next = hold(oneSample, last.film(), last.paths(), scene);
            if (next != null) {
                List<Shape> changed = SceneEdit.changedShapes(last.scene(), scene, origins);
                if (changed == null) {
                    next.paths().forgetAll();
                } else {
                    next.paths().forgetShapes(changed, scene.camera().position(), scene.lights());
                }
            }
        } else {
            if (last != null) {
                last.memory().close();
            }
            next = hold(oneSample, null, null, scene);
        }
        if (next != null) {
            kept.set(next);
            if (closed) {
                release(); // closed meanwhile: whichever of the two swaps it out gives the memory back
            }
        }
        return next;
    }

    private Kept hold(RenderSettings settings, Film film, PixelPaths paths, Scene scene) {
        if (closed) {
            return null;
        }
        long pixels = (long) settings.width() * settings.height();
        MemoryBudget.Reservation held = memory.tryReserveYielding(pixels * BYTES_PER_PIXEL + RenderMemory.sceneBytes(scene),
                this::drop);
        if (held == null) {
            return null;
        }
        return new Kept(settings, film != null ? film : new Film(settings.width(), settings.height()),
                paths != null ? paths : new PixelPaths(settings.width(), settings.height()), scene, held);
    }

    /** Gives the memory back until the next {@link #prepare}: a revision that keeps nothing, or other work needs the memory. */
    void drop() {
        release();
    }

    /** Gives the memory back; nothing is kept from now on. */
    @Override
    public void close() {
        closed = true;
        release();
    }

    private void release() {
        Kept dropped = kept.getAndSet(null);
        if (dropped != null) {
            dropped.memory().close();
        }
    }
}

package studio.engine.render;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.BooleanSupplier;

import studio.engine.camera.Camera;
import studio.engine.geometry.Ray;
import studio.engine.math.Rgb;
import studio.engine.sampler.PixelRandom;
import studio.engine.sampler.Sampler;
import studio.engine.scene.Scene;

/**
 * Renders a scene into a {@link Film}: the image is cut into tiles, the tiles run on a
 * ForkJoinPool of the requested size, each finished tile is reported, and a cancel request is
 * honoured between tiles. Each pixel's samples are seeded from the pixel, so the result is the
 * same, bit for bit, whatever the number of threads.
 */
public final class Renderer {

    private Renderer() {
    }

    public static RenderResult render(Scene scene, RenderSettings settings) {
        return render(scene, settings, RenderListener.NONE, () -> false);
    }

    /**
     * Renders the scene.
     *
     * @throws RenderCancelledException if {@code cancelled} turned true before the last tile
     */
    public static RenderResult render(Scene scene, RenderSettings settings, RenderListener listener,
                                     BooleanSupplier cancelled) {
        long start = System.nanoTime();
        Film film = new Film(settings.width(), settings.height());
        List<TileRect> tiles = tiles(settings.width(), settings.height(), RenderSettings.TILE_SIZE);
        AtomicInteger done = new AtomicInteger();
        LongAdder rays = new LongAdder();
        LongAdder nonFinite = new LongAdder();
        ThreadLocal<TileWorker> workers = ThreadLocal.withInitial(() -> new TileWorker(scene, settings));

        ForkJoinPool pool = new ForkJoinPool(settings.effectiveThreads());
        try {
            List<Future<?>> futures = new ArrayList<>(tiles.size());
            for (TileRect tile : tiles) {
                futures.add(pool.submit(() -> {
                    if (cancelled.getAsBoolean()) {
                        return;
                    }
                    TileWorker worker = workers.get();
                    long raysBefore = worker.integrator.rays;
                    long bad = worker.render(film, tile);
                    rays.add(worker.integrator.rays - raysBefore);
                    nonFinite.add(bad);
                    listener.tileFinished(film, tile, done.incrementAndGet(), tiles.size());
                }));
            }
            for (Future<?> future : futures) {
                future.get();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new RenderCancelledException();
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            if (cause instanceof RuntimeException runtime) {
                throw runtime;
            }
            if (cause instanceof Error error) {
                throw error;
            }
            throw new IllegalStateException(cause);
        } finally {
            pool.shutdownNow();
        }
        if (done.get() < tiles.size()) {
            throw new RenderCancelledException();
        }
        return new RenderResult(film, rays.sum(), nonFinite.sum(), System.nanoTime() - start);
    }

    /** The image cut into tiles of at most size x size, row by row from the top left. */
    static List<TileRect> tiles(int width, int height, int size) {
        List<TileRect> tiles = new ArrayList<>();
        for (int y = 0; y < height; y += size) {
            for (int x = 0; x < width; x += size) {
                tiles.add(new TileRect(x, y, Math.min(size, width - x), Math.min(size, height - y)));
            }
        }
        return tiles;
    }

    /** Per-thread state: the integrator, the random generator and the sample buffers. */
    private static final class TileWorker {
        final Integrator integrator;
        final Camera camera;
        final Sampler sampler;
        final PixelRandom random = new PixelRandom();
        final double[] xs, ys;
        final int width, height;
        final double aspect;
        final long seed;

        TileWorker(Scene scene, RenderSettings settings) {
            integrator = new Integrator(scene, settings.maxDepth(), settings.minPathWeight());
            camera = scene.camera();
            sampler = settings.sampler();
            xs = new double[sampler.samplesPerPixel()];
            ys = new double[sampler.samplesPerPixel()];
            width = settings.width();
            height = settings.height();
            aspect = (double) width / height;
            seed = settings.seed();
        }

        /** Renders one tile into the film; returns how many pixels came out non-finite. */
        long render(Film film, TileRect tile) {
            long bad = 0;
            int n = sampler.samplesPerPixel();
            for (int y = tile.y(); y < tile.y() + tile.height(); y++) {
                for (int x = tile.x(); x < tile.x() + tile.width(); x++) {
                    random.reset(x, y, seed);
                    sampler.generate(random, xs, ys);
                    double r = 0, g = 0, b = 0;
                    for (int s = 0; s < n; s++) {
                        double ndcX = 2 * (x + xs[s]) / width - 1;
                        double ndcY = 1 - 2 * (y + ys[s]) / height;
                        Ray ray = camera.ray(ndcX, ndcY, aspect);
                        Rgb c = integrator.trace(ray, 0, 1.0 / n);
                        if (Double.isFinite(c.r()) && Double.isFinite(c.g()) && Double.isFinite(c.b())) {
                            r += c.r();
                            g += c.g();
                            b += c.b();
                        } else {
                            bad++;
                        }
                    }
                    film.set(x, y, r / n, g / n, b / n);
                }
            }
            return bad;
        }
    }
}

package studio.engine.render;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.BooleanSupplier;

import studio.engine.sampler.SobolSampler;
import studio.engine.scene.Scene;

/**
 * Renders a scene into a {@link Film}: the image is cut into tiles, each tile is a task that a
 * {@link TileRenderer} (one per thread) renders, the tasks run on a ForkJoinPool of the requested
 * size, each finished tile is reported, and a cancel request stops the render within a few
 * milliseconds and a camera sample, inside a tile too. Each pixel's samples are seeded from the
 * pixel, so the result is the same, bit for bit, whatever the number of threads and whichever
 * worker renders which tile.
 *
 * <p>How a pixel takes its samples is the settings' {@link TileSampling} strategy: all of the
 * sampler's ({@link FixedSampling}); adaptively, in batches of fresh patterns
 * ({@link BatchAdaptiveSampling}); or adaptively along one Sobol sequence, judged with its
 * neighbours ({@link ProgressiveSobolSampling}, whose tiles share their edges' samples through
 * {@link TileBorders}).
 */
public final class Renderer {

    /** Fewer tiles than this per thread get smaller tiles (see {@link #tileSize}). */
    static final int TILES_PER_THREAD = 16;
    /**
     * While tiles are rendered, the calling thread asks the cancel condition this often: a render
     * stops within this and one camera sample of its cancel or deadline.
     */
    static final long POLL_MILLIS = 5;
    /**
     * Each tile's CPU time, by its thread's own clock ({@link RenderResult#cpuNanos}): two reads a
     * tile of 32x32 pixels, against the process's CPU time, which the JVM reports here in steps of
     * 10 ms, too coarse for a render of tens of milliseconds.
     */
    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

    private Renderer() {
    }

    /**
     * Renders what the request asks: its {@code pixels} not on its {@code except} and not known to
     * its {@code paths} into its film, which has the settings' size (the film's other pixels are
     * left as they are). Each pixel comes out as in a whole render, so rendering nested lattices one
     * after the other (see {@link PixelLattice}) fills the film with the whole render's pixels; a
     * lattice other than every pixel is only for fixed sampling (adaptive sampling with sobol judges
     * a pixel by its neighbours). {@code cancelled} is asked before each tile and, while tiles are
     * being rendered, every {@value #POLL_MILLIS} ms by the calling thread (never per sample: it may
     * be slow); once it answers true, every tile stops within one camera sample (see
     * {@link StopSignal}). The render returns or throws once no tile is being rendered any more
     * (unless the calling thread is interrupted: then at once, and the tiles stop within a sample).
     *
     * @throws RenderCancelledException if {@code cancelled} turned true before the last tile was done
     * @throws IllegalArgumentException if the settings are adaptive (and the lattice is not every
     *                                  pixel), or the film's size is not the settings'
     */
    public static RenderResult render(RenderRequest request) {
        Scene scene = request.scene();
        RenderSettings settings = request.settings();
        Film film = request.film();
        PixelLattice pixels = request.pixels(), except = request.except();
        PixelPaths paths = request.paths();
        RenderListener listener = request.listener();
        BooleanSupplier cancelled = request.cancelled();
        if (film.width() != settings.width() || film.height() != settings.height()) {
            throw new IllegalArgumentException("the film is " + film.width() + "x" + film.height()
                    + ", the settings " + settings.width() + "x" + settings.height());
        }
        TileRenderer.requireLattice(settings, pixels, except, paths);
        long start = System.nanoTime();
        int tileSize = tileSize(settings.width(), settings.height(), settings.effectiveThreads());
        List<TileRect> tiles = tiles(settings.width(), settings.height(), tileSize);
        // adaptive sampling with sobol is progressive: its tiles share their edges' base samples
        TileBorders borders = settings.adaptive() && settings.sampler() instanceof SobolSampler
                ? new TileBorders(settings.width(), settings.height(), tileSize) : null;
        StopSignal stop = new StopSignal();
        CountDownLatch ended = new CountDownLatch(tiles.size());
        AtomicReference<Throwable> failure = new AtomicReference<>();
        AtomicInteger done = new AtomicInteger();
        LongAdder rays = new LongAdder();
        LongAdder samples = new LongAdder();
        LongAdder nonFinite = new LongAdder();
        LongAdder cpuNanos = new LongAdder();
        ThreadLocal<TileRenderer> workers = ThreadLocal.withInitial(
                () -> new TileRenderer(scene, settings, borders, stop));

        ForkJoinPool pool = new ForkJoinPool(settings.effectiveThreads());
        try {
            for (TileRect tile : tiles) {
                pool.execute(() -> {
                    try {
                        if (stop.raised() || cancelled.getAsBoolean()) {
                            stop.raise();
                            return;
                        }
                        TileRenderer worker = workers.get();
                        long raysBefore = worker.rays(), samplesBefore = worker.samples();
                        long cpuBefore = THREADS.getCurrentThreadCpuTime();
                        long bad = worker.render(request.tile(tile));
                        cpuNanos.add(THREADS.getCurrentThreadCpuTime() - cpuBefore);
                        rays.add(worker.rays() - raysBefore);
                        samples.add(worker.samples() - samplesBefore);
                        nonFinite.add(bad);
                        listener.tileFinished(film, tile, done.incrementAndGet(), tiles.size());
                    } catch (RenderCancelledException e) {
                        stop.raise();
                    } catch (RuntimeException | Error e) {
                        failure.compareAndSet(null, e);
                        stop.raise(); // the render has failed: the other tiles need not go on
                    } finally {
                        ended.countDown();
                    }
                });
            }
            while (!ended.await(POLL_MILLIS, TimeUnit.MILLISECONDS)) {
                if (!stop.raised() && cancelled.getAsBoolean()) {
                    stop.raise();
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new RenderCancelledException();
        } finally {
            stop.raise(); // a no-op unless the render ends early: interrupted, or the condition threw
            pool.shutdownNow();
        }
        Throwable failed = failure.get();
        if (failed instanceof RuntimeException runtime) {
            throw runtime;
        }
        if (failed instanceof Error error) {
            throw error;
        }
        if (done.get() < tiles.size()) {
            throw new RenderCancelledException();
        }
        return new RenderResult(film, rays.sum(), nonFinite.sum(), System.nanoTime() - start, samples.sum(),
                Math.max(0, cpuNanos.sum()));
    }

    /**
     * {@link RenderSettings#TILE_SIZE}, or half of it when that would leave fewer than
     * {@value #TILES_PER_THREAD} tiles per thread: with few tiles, the one that holds most of the work
     * (the edges, under adaptive sampling) would finish alone while the other threads wait.
     */
    public static int tileSize(int width, int height, int threads) {
        int size = RenderSettings.TILE_SIZE;
        long tiles = (long) ((width + size - 1) / size) * ((height + size - 1) / size);
        return tiles < (long) TILES_PER_THREAD * threads ? size / 2 : size;
    }

    /** The image cut into tiles of at most size x size, row by row from the top left. */
    public static List<TileRect> tiles(int width, int height, int size) {
        List<TileRect> tiles = new ArrayList<>();
        for (int y = 0; y < height; y += size) {
            for (int x = 0; x < width; x += size) {
                tiles.add(new TileRect(x, y, Math.min(size, width - x), Math.min(size, height - y)));
            }
        }
        return tiles;
    }
}

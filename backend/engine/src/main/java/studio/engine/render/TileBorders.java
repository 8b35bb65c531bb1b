package studio.engine.render;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;

/**
 * Adaptive sampling with sobol: the base samples of the pixels near the tiles' edges, shared between
 * neighbouring tiles. A tile judges its pixels by a ring of {@value #LINES} pixels of its neighbours'
 * ({@link ProgressiveSobolSampling}); whichever tile takes a pixel's base samples first leaves them
 * here, and the other reads them instead of tracing them again (on the stripes benchmark scene at
 * 320x240 a one-pixel ring was 7% of all rays). Base samples are seeded by pixel, so both tiles would
 * get the same values: the image does not depend on which tile went first, nor on the thread count.
 *
 * <p>Per pixel near an edge: its base sum, smallest and largest sample per channel, how many
 * samples came out non-finite, and the light its penumbra may hide ({@link SampleTracer#penumbraLight}).
 * {@value #LINES} x 2 rows per row of tiles (its first and last) and as many columns per column of
 * tiles; a pixel near a corner is kept with its row. About 2 x 2 x {@value #LINES} / size of the
 * image's pixels at 88 bytes each: 22 bytes a pixel with 32-pixel tiles.
 */
final class TileBorders {

    private static final VarHandle STATE = MethodHandles.arrayElementVarHandle(int[].class);
    private static final int FREE = 0, CLAIMED = 1, STORED = 2;
    private static final int VALUES = 9;
    /** The lines along each edge of a tile that the neighbouring tile's ring holds. */
    static final int LINES = 2;

    private final int width, height, size;
    private final int rowEntries;
    /** Per entry: sum r, g, b, min r, g, b, max r, g, b; rows' entries first, then columns'. */
    private final double[] values;
    private final int[] nonFinite;
    /** Per entry: {@link SampleTracer#penumbraLight} of its base samples. */
    private final double[] penumbra;
    /** Per entry FREE, CLAIMED (a tile is tracing it) or STORED (its values are written: release/acquire). */
    private final int[] states;

    TileBorders(int width, int height, int size) {
        this.width = width;
        this.height = height;
        this.size = size;
        int tileRows = (height + size - 1) / size, tileColumns = (width + size - 1) / size;
        rowEntries = 2 * LINES * tileRows * width;
        int entries = rowEntries + 2 * LINES * tileColumns * height;
        values = new double[VALUES * entries];
        nonFinite = new int[entries];
        penumbra = new double[entries];
        states = new int[entries];
    }

    /** Pixel (x, y)'s entry, or -1 if it lies deep inside its tile (no other tile's ring holds it). */
    int entryOf(int x, int y) {
        int slot = edgeSlot(y, height);
        if (slot >= 0) {
            return (2 * LINES * (y / size) + slot) * width + x;
        }
        slot = edgeSlot(x, width);
        return slot < 0 ? -1 : rowEntries + (2 * LINES * (x / size) + slot) * height + y;
    }

    /**
     * 0 .. {@value #LINES} - 1 on a tile's first lines, {@value #LINES} .. 2 {@value #LINES} - 1 on
     * its last (the image's last tile may be narrower), -1 in between; a line both among the first and
     * among the last of a narrow tile counts with the first.
     */
    private int edgeSlot(int coordinate, int extent) {
        int within = coordinate % size;
        if (within < LINES) {
            return within;
        }
        int fromEnd = Math.min(size, extent - (coordinate - within)) - 1 - within;
        return fromEnd < LINES ? 2 * LINES - 1 - fromEnd : -1;
    }

    /**
     * Copies an entry's base sum, minima and maxima into the arrays at {@code at} (3 values each) and
     * returns its count of non-finite samples; or returns -1 when no tile has taken them yet: the
     * caller then owns the entry and must {@link #store} it (or {@link #abandon} it if tracing
     * fails or the render stops). While another tile traces an entry it waits for it (a few rays),
     * so no base sample is ever traced twice and the rays traced, too, are the same at any thread
     * count; but not once the render is stopping, when the other tile may never store it.
     *
     * @throws RenderCancelledException if {@code stop} is raised while the entry is claimed by another tile
     */
    int loadOrClaim(int entry, double[] sum, double[] min, double[] max, int at, StopSignal stop) {
        while (true) {
            int state = (int) STATE.getAcquire(states, entry);
            if (state == STORED) {
                int v = VALUES * entry;
                System.arraycopy(values, v, sum, at, 3);
                System.arraycopy(values, v + 3, min, at, 3);
                System.arraycopy(values, v + 6, max, at, 3);
                return nonFinite[entry];
            }
            if (state == FREE && STATE.compareAndSet(states, entry, FREE, CLAIMED)) {
                return -1;
            }
            stop.check();
            Thread.onSpinWait();
        }
    }

    /** The bytes its arrays hold (the server's render estimate counts them per pixel: {@code RenderMemory}). */
    long bytes() {
        return 8L * values.length + 4L * nonFinite.length + 8L * penumbra.length + 4L * states.length;
    }

    /** The penumbra light stored with an entry that {@link #loadOrClaim} found stored. */
    double penumbraLight(int entry) {
        return penumbra[entry];
    }

    /** Leaves a claimed entry's values for the neighbouring tile. */
    void store(int entry, double[] sum, double[] min, double[] max, int at, int bad, double penumbraLight) {
        int v = VALUES * entry;
        System.arraycopy(sum, at, values, v, 3);
        System.arraycopy(min, at, values, v + 3, 3);
        System.arraycopy(max, at, values, v + 6, 3);
        nonFinite[entry] = bad;
        penumbra[entry] = penumbraLight;
        STATE.setRelease(states, entry, STORED);
    }

    /**
     * Frees a claimed entry whose tracing failed or was stopped, so that no other tile waits for it
     * forever: the tile that waits claims it next, and traces it or, if the render is stopping,
     * gives it up in turn.
     */
    void abandon(int entry) {
        STATE.setRelease(states, entry, FREE);
    }
}

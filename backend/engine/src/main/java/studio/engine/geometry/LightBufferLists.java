package studio.engine.geometry;

import java.util.Arrays;

import studio.engine.accel.Aabb;
import studio.engine.memory.MemoryGate;

/**
 * Building a {@link LightBuffer}'s lists: the grid over the primitives' projected rectangles, each
 * cell listing the primitives whose rectangle (widened by {@link LightBuffer#UV_MARGIN}) overlaps
 * it, nearest the light first. Setup code, run once per buffer.
 */
final class LightBufferLists {

    private LightBufferLists() {
    }

    /** The grid over the projected rectangles (uMin, uMax, vMin, vMax each) and the lists, nearest first. */
    static LightBuffer assemble(LightBuffer.Frame f, double[] rects, float[] bounds,
                                LightBuffer.Primitives primitives, MemoryGate memory) {
        int count = bounds.length;
        if (count == 0) {
            return null;
        }
        // cells about as large as a primitive's projected rectangle on average
        double[] sums = new double[2];
        Runs.over(count, (from, to) -> {
            for (int t = from; t < to; t++) {
                sums[0] += rects[4 * t + 1] - rects[4 * t];
                sums[1] += rects[4 * t + 3] - rects[4 * t + 2];
            }
        });
        double sumU = sums[0], sumV = sums[1];
        double spanU = f.uMax() - f.uMin(), spanV = f.vMax() - f.vMin();
        double cellU = Math.max(LightBuffer.CELL_SIZE * sumU / count, spanU / LightBuffer.MAX_SIDE);
        double cellV = Math.max(LightBuffer.CELL_SIZE * sumV / count, spanV / LightBuffer.MAX_SIDE);
        int nu = (int) Math.max(1, Math.min(LightBuffer.MAX_SIDE, Math.ceil(spanU / cellU)));
        int nv = (int) Math.max(1, Math.min(LightBuffer.MAX_SIDE, Math.ceil(spanV / cellV)));
        while ((long) nu * nv > Math.min(LightBuffer.MAX_CELLS, 4L * count + 16)) {
            nu = Math.max(1, nu / 2);
            nv = Math.max(1, nv / 2);
        }
        int cells = nu * nv, columns = nu, rows = nv;
        double perU = nu / spanU, perV = nv / spanV;
        if (!memory.tryReserve(MemoryGate.ints(4L * count) + MemoryGate.ints(cells + 1L))) {
            return null;
        }

        // each primitive's cells (i0, i1, j0, j1) and the lists' lengths
        int[] range = new int[4 * count];
        int[] cellStart = new int[cells + 1];
        long[] counted = new long[1];
        long cap = (long) LightBuffer.MAX_ENTRIES_PER_PRIMITIVE * count + cells;
        Runs.over(count, (from, to) -> {
            for (int t = from; t < to && counted[0] <= cap; t++) {
                int i0 = cell(rects[4 * t] - LightBuffer.UV_MARGIN, f.uMin(), perU, columns);
                int i1 = cell(rects[4 * t + 1] + LightBuffer.UV_MARGIN, f.uMin(), perU, columns);
                int j0 = cell(rects[4 * t + 2] - LightBuffer.UV_MARGIN, f.vMin(), perV, rows);
                int j1 = cell(rects[4 * t + 3] + LightBuffer.UV_MARGIN, f.vMin(), perV, rows);
                range[4 * t] = i0;
                range[4 * t + 1] = i1;
                range[4 * t + 2] = j0;
                range[4 * t + 3] = j1;
                counted[0] += (long) (i1 - i0 + 1) * (j1 - j0 + 1);
                for (int j = j0; j <= j1; j++) {
                    for (int i = i0; i <= i1; i++) {
                        cellStart[j * columns + i + 1]++;
                    }
                }
            }
        });
        long entries = counted[0];
        if (entries > cap) {
            return null;
        }
        prefixSums(cellStart, cells);
        if (3 * entries > Integer.MAX_VALUE - 8
                || !memory.tryReserve(MemoryGate.ints(3 * entries) + MemoryGate.ints(cells)
                + 2 * MemoryGate.ints(count + 1L))) {
            return null;
        }
        int[] packed = new int[3 * (int) entries];
        // the primitives in about the order of their bounds (a counting sort on a grid of them), so
        // that each cell's list comes out nearly sorted and its sort has little left to do
        float[] extent = {Float.POSITIVE_INFINITY, 0}; // the least and the most bound
        Runs.over(count, (from, to) -> {
            float least = extent[0], most = extent[1];
            for (int t = from; t < to; t++) {
                least = Math.min(least, bounds[t]);
                most = Math.max(most, bounds[t]);
            }
            extent[0] = least;
            extent[1] = most;
        });
        float least = extent[0], most = extent[1];
        double perBound = most > least ? (count - 1) / ((double) most - least) : 0;
        int[] bucketStart = new int[count + 1];
        Runs.over(count, (from, to) -> {
            for (int t = from; t < to; t++) {
                bucketStart[bucket(bounds[t], least, perBound, count) + 1]++;
            }
        });
        prefixSums(bucketStart, count);
        int[] order = new int[count];
        Runs.over(count, (from, to) -> {
            for (int t = from; t < to; t++) {
                order[bucketStart[bucket(bounds[t], least, perBound, count)]++] = t;
            }
        });
        int[] next = Arrays.copyOf(cellStart, cells);
        Runs.over(count, (from, to) -> {
            for (int q = from; q < to; q++) {
                int t = order[q];
                float bound = bounds[t];
                // the rectangle in cells, as LightBuffer.occluder works out a ray's
                double uLow = (rects[4 * t] - LightBuffer.UV_MARGIN - f.uMin()) * perU;
                double uHigh = (rects[4 * t + 1] + LightBuffer.UV_MARGIN - f.uMin()) * perU;
                double vLow = (rects[4 * t + 2] - LightBuffer.UV_MARGIN - f.vMin()) * perV;
                double vHigh = (rects[4 * t + 3] + LightBuffer.UV_MARGIN - f.vMin()) * perV;
                for (int j = range[4 * t + 2]; j <= range[4 * t + 3]; j++) {
                    for (int i = range[4 * t]; i <= range[4 * t + 1]; i++) {
                        int at = next[j * columns + i]++;
                        packed[3 * at] = t;
                        packed[3 * at + 1] = Float.floatToRawIntBits(bound);
                        packed[3 * at + 2] = LightBuffer.span(uLow, uHigh, vLow, vHigh, i, j);
                    }
                }
            }
        });
        Runs.over(cells, (from, to) -> {
            for (int cell = from; cell < to; cell++) {
                sortByNearest(packed, cellStart[cell], cellStart[cell + 1]);
            }
        });
        return new LightBuffer(f, primitives, nu, nv, cellStart, packed);
    }

    /**
     * A lower bound of the distance from the light to the box at {@code box[o ..]}: its distance,
     * shrunk by a millionth and rounded down to a float.
     */
    static float nearestBound(double[] box, int o, double[] l) {
        float bound = (float) (Aabb.distance(box, o, l[0], l[1], l[2]) * (1 - 1e-6));
        return bound > 0 ? Math.nextDown(bound) : 0;
    }

    /** Turns counts at {@code a[1 .. n]} into starts: each a[q + 1] becomes a[0] + ... + a[q + 1]. */
    private static void prefixSums(int[] a, int n) {
        Runs.over(n, (from, to) -> {
            for (int q = from; q < to; q++) {
                a[q + 1] += a[q];
            }
        });
    }

    /** The counting sort's bucket of a bound. */
    private static int bucket(float bound, float least, double perBound, int count) {
        return Math.min(count - 1, (int) (((double) bound - least) * perBound));
    }

    /** The cell of a projected coordinate, clamped to the grid. */
    private static int cell(double u, double min, double perCell, int n) {
        double at = (u - min) * perCell;
        return at < 0 ? 0 : at >= n ? n - 1 : (int) at;
    }

    /** Insertion sort of one cell's entries (three ints each) by their bound (lists are short). */
    private static void sortByNearest(int[] packed, int from, int to) {
        for (int i = from + 1; i < to; i++) {
            int t = packed[3 * i], bits = packed[3 * i + 1], span = packed[3 * i + 2];
            float key = Float.intBitsToFloat(bits);
            int j = i - 1;
            while (j >= from && Float.intBitsToFloat(packed[3 * j + 1]) > key) {
                System.arraycopy(packed, 3 * j, packed, 3 * j + 3, 3);
                j--;
            }
            packed[3 * j + 3] = t;
            packed[3 * j + 4] = bits;
            packed[3 * j + 5] = span;
        }
    }
}

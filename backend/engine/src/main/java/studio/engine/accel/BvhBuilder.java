package studio.engine.accel;

import java.util.Arrays;

import studio.engine.geometry.Runs;
import studio.engine.memory.MemoryGate;

/**
 * Builds a {@link Bvh} top-down with the binned surface area heuristic (Wald 2007; pbrt's
 * BuildRecursive): the centroids of a node's primitives are sorted into up to {@value #BINS} bins
 * along the axis where the centroids spread most, and the cheapest bin boundary is taken, or a leaf
 * if that is cheaper and holds at most {@link Bvh#LEAF_MAX} primitives. When the centroids
 * coincide, or the tree reaches {@value #SAH_DEPTH} levels, it falls back to a median split, which
 * halves the primitive count each level and so bounds the depth by {@link Bvh#STACK_SIZE}.
 *
 * <p>Built for a million primitives in well under a second: primitive arrays only, the boxes
 * copied once into slot order and partitioned in place, scratch bins reused for every node, and
 * each child's box and centroid bounds worked out while its parent is split (from the bins and
 * during the partition), so no node scans its primitives just to bound them.
 *
 * <p>Every array it allocates or grows is first asked of a {@link MemoryGate}: for n primitives,
 * the copied boxes (48n bytes), the slots (4n) and the nodes (60 bytes each, at most 2n - 1; the
 * arrays start at n/2 nodes and double).
 */
final class BvhBuilder {

    static final int BINS = 16;
    /** Below this many levels splits follow the SAH; deeper, the median (see the class comment). */
    static final int SAH_DEPTH = 32;
    /**
     * Cost of visiting a node relative to testing one primitive. In this engine a box test and a
     * watertight triangle test cost about the same; against pbrt's 1/8 it halves the node count
     * (1M triangles: 0.95M nodes instead of 1.9M) at no measurable loss of ray speed.
     */
    private static final double TRAVERSAL_COST = 1;
    /** Doubles of pending node data: box (6), centroid minima (3) and maxima (3), centroids as min+max. */
    private static final int INFO = 12;

    /** Primitive boxes in slot order, six doubles per slot; partitioned together with {@link #ids}. */
    private final double[] box;
    private final int[] ids;
    private final MemoryGate memory;
    private double[] nodeBounds;
    private int[] nodeLinks;
    private int nodeCount;
    private int maxDepth;
    /** The last slot {@link #partitionRun} has not looked at yet. */
    private int partitionLast;

    /** The box and centroid bounds of the two children waiting at each depth (left, right). */
    private final double[] pending = new double[(Bvh.STACK_SIZE + 2) * 2 * INFO];
    /** Scratch bins along one axis: count and box. */
    private final int[] binCount = new int[BINS];
    private final double[] binBox = new double[6 * BINS];
    private final double[] rightArea = new double[BINS];
    private final int[] rightCount = new int[BINS];

    BvhBuilder(double[] primitiveBounds, int count, MemoryGate memory) {
        if (count <= 0 || primitiveBounds.length < 6L * count) {
            throw new IllegalArgumentException("a BVH needs at least one primitive box; got " + count);
        }
        int capacity = Math.max(1, count / 2);
        memory.reserve(MemoryGate.doubles(6L * count) + MemoryGate.ints(count) + MemoryGate.doubles(6L * capacity)
                + MemoryGate.ints(3L * capacity));
        this.memory = memory;
        box = Arrays.copyOf(primitiveBounds, 6 * count);
        ids = new int[count];
        // The loops over a node's slots (checking, bounding, binning, partitioning) run Runs.LENGTH slots a
        // call, as Runs does (the root's cover every primitive, and a render process would run them
        // interpreted to their end), written out: Runs.over's capturing lambdas would allocate at every
        // node, memory the gate was not asked for (BvhTest.buildAsksTheGateForWhatItAllocates).
        for (int from = 0; from < count; from += Runs.LENGTH) {
            startRun(from, Math.min(count, from + Runs.LENGTH));
        }
        nodeBounds = new double[6 * capacity];
        nodeLinks = new int[3 * capacity];
    }

    /** Checks the boxes of slots [from, to) and numbers them. */
    private void startRun(int from, int to) {
        double[] b = box;
        for (int i = 6 * from, end = 6 * to; i < end; i++) {
            if (!Double.isFinite(b[i])) {
                throw new IllegalArgumentException("primitive boxes must be finite");
            }
        }
        for (int i = from; i < to; i++) {
            ids[i] = i;
        }
    }

    Bvh build() {
        long start = System.nanoTime();
        scanBounds(0, ids.length, slot(1, 0));
        buildNode(0, ids.length, 1, slot(1, 0));
        memory.reserve(MemoryGate.doubles(6L * nodeCount) + MemoryGate.ints(3L * nodeCount));
        return new Bvh(Arrays.copyOf(nodeBounds, 6 * nodeCount), Arrays.copyOf(nodeLinks, 3 * nodeCount), ids,
                maxDepth, System.nanoTime() - start);
    }

    /** Offset in {@link #pending} of the left (0) or right (1) child at a depth. */
    private static int slot(int depth, int side) {
        return (2 * depth + side) * INFO;
    }

    /**
     * Builds the subtree over slots [start, end) at the given depth (root = 1), whose box and
     * centroid bounds wait at {@code pending[info ..]}; returns its node index.
     */
    private int buildNode(int start, int end, int depth, int info) {
        int node = nodeCount++;
        if (nodeCount * 3 > nodeLinks.length) {
            memory.reserve(MemoryGate.ints(nodeLinks.length * 2L) + MemoryGate.doubles(nodeBounds.length * 2L));
            nodeLinks = Arrays.copyOf(nodeLinks, nodeLinks.length * 2);
            nodeBounds = Arrays.copyOf(nodeBounds, nodeBounds.length * 2);
        }
        maxDepth = Math.max(maxDepth, depth);
        double[] p = pending;
        System.arraycopy(p, info, nodeBounds, 6 * node, 6);
        int n = end - start;
        if (n == 1) {
            return leaf(node, start, n);
        }
        double ex = p[info + 9] - p[info + 6], ey = p[info + 10] - p[info + 7], ez = p[info + 11] - p[info + 8];
        int axis = ex >= ey && ex >= ez ? 0 : ey >= ez ? 1 : 2;
        double extent = axis == 0 ? ex : axis == 1 ? ey : ez;
        int left = slot(depth + 1, 0), right = slot(depth + 1, 1);
        int mid = -1;
        if (depth < SAH_DEPTH && extent > 0) {
            int bins = Math.min(BINS, n);
            double cmin = p[info + 6 + axis];
            double scale = bins * (1 - 1e-9) / extent;
            if (Double.isFinite(scale)) {
                double area = halfArea(p, info);
                int split = findSplit(start, end, axis, cmin, scale, bins, area, n);
                if (split == 0) {
                    return leaf(node, start, n);
                }
                if (split > 0) {
                    mid = partition(start, end, axis, cmin, scale, bins, split, left, right);
                }
            }
        }
        if (mid < 0) {
            if (n <= Bvh.LEAF_MAX) {
                return leaf(node, start, n);
            }
            mid = (start + end) >>> 1;
            if (extent > 0) {
                select(start, end, mid, axis);
            }
            scanBounds(start, mid, left);
            scanBounds(mid, end, right);
        }
        buildNode(start, mid, depth + 1, left);
        int rightChild = buildNode(mid, end, depth + 1, right);
        nodeLinks[3 * node] = rightChild;
        nodeLinks[3 * node + 1] = ~axis;
        nodeLinks[3 * node + 2] = nodeCount;
        return node;
    }

    private int leaf(int node, int start, int n) {
        nodeLinks[3 * node] = start;
        nodeLinks[3 * node + 1] = n;
        nodeLinks[3 * node + 2] = nodeCount;
        return node;
    }

    /** Writes the box and centroid bounds of slots [start, end) to {@code pending[info ..]}. */
    private void scanBounds(int start, int end, int info) {
        double[] p = pending;
        for (int k = 0; k < 3; k++) {
            p[info + k] = p[info + 6 + k] = Double.POSITIVE_INFINITY;
            p[info + 3 + k] = p[info + 9 + k] = Double.NEGATIVE_INFINITY;
        }
        for (int from = start; from < end; from += Runs.LENGTH) {
            scanRun(from, Math.min(end, from + Runs.LENGTH), info);
        }
    }

    /** {@link #scanBounds}' loop over slots [from, to), widening the bounds at {@code pending[info ..]}. */
    private void scanRun(int from, int to, int info) {
        double[] p = pending;
        for (int s = from; s < to; s++) {
            int o = 6 * s;
            for (int k = 0; k < 3; k++) {
                double lo = box[o + k], hi = box[o + k + 3], c = lo + hi;
                if (lo < p[info + k]) p[info + k] = lo;
                if (hi > p[info + 3 + k]) p[info + 3 + k] = hi;
                if (c < p[info + 6 + k]) p[info + 6 + k] = c;
                if (c > p[info + 9 + k]) p[info + 9 + k] = c;
            }
        }
    }

    private static double halfArea(double[] b, int o) {
        double dx = b[o + 3] - b[o], dy = b[o + 4] - b[o + 1], dz = b[o + 5] - b[o + 2];
        return dx * dy + dy * dz + dz * dx;
    }

    private static int bin(double centroid, double cmin, double scale, int bins) {
        int k = (int) ((centroid - cmin) * scale);
        return k < 0 ? 0 : k >= bins ? bins - 1 : k;
    }

    /** Counts slots [from, to) into their centroids' bins along the axis and widens the bins' boxes. */
    private void binRun(int from, int to, int axis, double cmin, double scale, int bins) {
        double[] bb = binBox, b = box;
        int[] counts = binCount;
        for (int s = from; s < to; s++) {
            int o = 6 * s;
            int k = bin(b[o + axis] + b[o + axis + 3], cmin, scale, bins);
            counts[k]++;
            int q = 6 * k;
            bb[q] = Math.min(bb[q], b[o]);
            bb[q + 1] = Math.min(bb[q + 1], b[o + 1]);
            bb[q + 2] = Math.min(bb[q + 2], b[o + 2]);
            bb[q + 3] = Math.max(bb[q + 3], b[o + 3]);
            bb[q + 4] = Math.max(bb[q + 4], b[o + 4]);
            bb[q + 5] = Math.max(bb[q + 5], b[o + 5]);
        }
    }

    /**
     * Bins the slots' centroids along the axis and returns the cheapest split as the first bin of
     * the right side (1 .. bins-1); 0 if a leaf is cheaper and small enough; -1 if no boundary
     * separates the centroids.
     */
    private int findSplit(int start, int end, int axis, double cmin, double scale, int bins, double area, int n) {
        double[] bb = binBox;
        Arrays.fill(binCount, 0, bins, 0);
        for (int k = 0; k < bins; k++) {
            int q = 6 * k;
            bb[q] = bb[q + 1] = bb[q + 2] = Double.POSITIVE_INFINITY;
            bb[q + 3] = bb[q + 4] = bb[q + 5] = Double.NEGATIVE_INFINITY;
        }
        for (int from = start; from < end; from += Runs.LENGTH) {
            binRun(from, Math.min(end, from + Runs.LENGTH), axis, cmin, scale, bins);
        }
        // Sweep from the right: count and area of bins k .. bins-1.
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        int count = 0;
        for (int k = bins - 1; k > 0; k--) {
            int q = 6 * k;
            count += binCount[k];
            x0 = Math.min(x0, bb[q]); y0 = Math.min(y0, bb[q + 1]); z0 = Math.min(z0, bb[q + 2]);
            x1 = Math.max(x1, bb[q + 3]); y1 = Math.max(y1, bb[q + 4]); z1 = Math.max(z1, bb[q + 5]);
            rightCount[k] = count;
            rightArea[k] = count == 0 ? 0 : (x1 - x0) * (y1 - y0) + (y1 - y0) * (z1 - z0) + (z1 - z0) * (x1 - x0);
        }
        x0 = Double.POSITIVE_INFINITY; y0 = x0; z0 = x0; x1 = Double.NEGATIVE_INFINITY; y1 = x1; z1 = x1;
        count = 0;
        double bestCost = Double.POSITIVE_INFINITY;
        int best = -1;
        for (int k = 1; k < bins; k++) {
            int q = 6 * (k - 1);
            count += binCount[k - 1];
            x0 = Math.min(x0, bb[q]); y0 = Math.min(y0, bb[q + 1]); z0 = Math.min(z0, bb[q + 2]);
            x1 = Math.max(x1, bb[q + 3]); y1 = Math.max(y1, bb[q + 4]); z1 = Math.max(z1, bb[q + 5]);
            if (count == 0 || rightCount[k] == 0) {
                continue;
            }
            double leftArea = (x1 - x0) * (y1 - y0) + (y1 - y0) * (z1 - z0) + (z1 - z0) * (x1 - x0);
            double cost = count * leftArea + rightCount[k] * rightArea[k];
            if (cost < bestCost) {
                bestCost = cost;
                best = k;
            }
        }
        if (best < 0) {
            return -1;
        }
        // Both costs scaled by the node's area: leaf n*area, split TRAVERSAL_COST*area + sum(count*area).
        if (n <= Bvh.LEAF_MAX && n * area <= TRAVERSAL_COST * area + bestCost) {
            return 0;
        }
        return best;
    }

    /**
     * Moves the slots whose centroid bin is below {@code split} to the front, writing each side's
     * box and centroid bounds to {@code pending[left ..]} and {@code pending[right ..]}; returns the
     * first slot of the right side. The two sides' bounds are widened in {@code pending} run by run
     * ({@link #partitionRun}).
     */
    private int partition(int start, int end, int axis, double cmin, double scale, int bins, int split,
                          int left, int right) {
        double[] p = pending;
        for (int k = 0; k < 6; k++) {
            p[left + k] = p[left + 6 + k] = p[right + k] = p[right + 6 + k] = k < 3 ? Double.POSITIVE_INFINITY
                    : Double.NEGATIVE_INFINITY;
        }
        partitionLast = end - 1;
        int i = start;
        while (i <= partitionLast) {
            i = partitionRun(i, axis, cmin, scale, bins, split, left, right);
        }
        return i;
    }

    /**
     * Up to {@value Runs#LENGTH} steps of {@link #partition} from slot {@code i} to {@link #partitionLast}:
     * a slot left of the split stays and widens the left side's bounds, one right of it widens the
     * right side's and is swapped to the end; returns the next slot to look at and leaves the last
     * one not yet looked at in {@link #partitionLast}.
     */
    private int partitionRun(int i, int axis, double cmin, double scale, int bins, int split, int left, int right) {
        double[] b = box, p = pending;
        // Left and right: box (l*, r*) and centroid bounds (lc*, rc*), kept in locals for the run.
        double lx0 = p[left], ly0 = p[left + 1], lz0 = p[left + 2];
        double lx1 = p[left + 3], ly1 = p[left + 4], lz1 = p[left + 5];
        double lcx0 = p[left + 6], lcy0 = p[left + 7], lcz0 = p[left + 8];
        double lcx1 = p[left + 9], lcy1 = p[left + 10], lcz1 = p[left + 11];
        double rx0 = p[right], ry0 = p[right + 1], rz0 = p[right + 2];
        double rx1 = p[right + 3], ry1 = p[right + 4], rz1 = p[right + 5];
        double rcx0 = p[right + 6], rcy0 = p[right + 7], rcz0 = p[right + 8];
        double rcx1 = p[right + 9], rcy1 = p[right + 10], rcz1 = p[right + 11];
        int j = partitionLast;
        for (int steps = 0; steps < Runs.LENGTH && i <= j; steps++) {
            int o = 6 * i;
            double x0 = b[o], y0 = b[o + 1], z0 = b[o + 2], x1 = b[o + 3], y1 = b[o + 4], z1 = b[o + 5];
            double cx = x0 + x1, cy = y0 + y1, cz = z0 + z1;
            if (bin(axis == 0 ? cx : axis == 1 ? cy : cz, cmin, scale, bins) < split) {
                lx0 = Math.min(lx0, x0); ly0 = Math.min(ly0, y0); lz0 = Math.min(lz0, z0);
                lx1 = Math.max(lx1, x1); ly1 = Math.max(ly1, y1); lz1 = Math.max(lz1, z1);
                lcx0 = Math.min(lcx0, cx); lcy0 = Math.min(lcy0, cy); lcz0 = Math.min(lcz0, cz);
                lcx1 = Math.max(lcx1, cx); lcy1 = Math.max(lcy1, cy); lcz1 = Math.max(lcz1, cz);
                i++;
            } else {
                rx0 = Math.min(rx0, x0); ry0 = Math.min(ry0, y0); rz0 = Math.min(rz0, z0);
                rx1 = Math.max(rx1, x1); ry1 = Math.max(ry1, y1); rz1 = Math.max(rz1, z1);
                rcx0 = Math.min(rcx0, cx); rcy0 = Math.min(rcy0, cy); rcz0 = Math.min(rcz0, cz);
                rcx1 = Math.max(rcx1, cx); rcy1 = Math.max(rcy1, cy); rcz1 = Math.max(rcz1, cz);
                swap(i, j);
                j--;
            }
        }
        partitionLast = j;
        store(left, lx0, ly0, lz0, lx1, ly1, lz1, lcx0, lcy0, lcz0, lcx1, lcy1, lcz1);
        store(right, rx0, ry0, rz0, rx1, ry1, rz1, rcx0, rcy0, rcz0, rcx1, rcy1, rcz1);
        return i;
    }

    private void store(int info, double x0, double y0, double z0, double x1, double y1, double z1,
                       double cx0, double cy0, double cz0, double cx1, double cy1, double cz1) {
        double[] p = pending;
        p[info] = x0; p[info + 1] = y0; p[info + 2] = z0;
        p[info + 3] = x1; p[info + 4] = y1; p[info + 5] = z1;
        p[info + 6] = cx0; p[info + 7] = cy0; p[info + 8] = cz0;
        p[info + 9] = cx1; p[info + 10] = cy1; p[info + 11] = cz1;
    }

    /** Quickselect: reorders slots [start, end) so slot k holds the k-th smallest centroid on the axis. */
    private void select(int start, int end, int k, int axis) {
        int lo = start, hi = end - 1;
        while (lo < hi) {
            double pivot = centroid((lo + hi) >>> 1, axis);
            int i = lo, j = hi;
            while (i <= j) {
                while (centroid(i, axis) < pivot) i++;
                while (centroid(j, axis) > pivot) j--;
                if (i <= j) {
                    swap(i, j);
                    i++;
                    j--;
                }
            }
            if (k <= j) {
                hi = j;
            } else if (k >= i) {
                lo = i;
            } else {
                return;
            }
        }
    }

    private double centroid(int slot, int axis) {
        return box[6 * slot + axis] + box[6 * slot + axis + 3];
    }

    private void swap(int i, int j) {
        int t = ids[i];
        ids[i] = ids[j];
        ids[j] = t;
        int oi = 6 * i, oj = 6 * j;
        for (int c = 0; c < 6; c++) {
            double v = box[oi + c];
            box[oi + c] = box[oj + c];
            box[oj + c] = v;
        }
    }
}

package studio.engine.geometry;

import java.util.Arrays;

import studio.engine.accel.Aabb;
import studio.engine.math.Vec3;
import studio.engine.memory.MemoryGate;

/**
 * A light buffer (Haines and Greenberg 1986): primitives (a mesh's triangles, a scene's objects)
 * as seen from one point light, binned by direction, so that a shadow ray towards that light tests
 * only the few that lie in its direction, nearest the light first, instead of searching a BVH.
 *
 * <p>The primitives' box must lie wholly on one side of the light along some axis (the depth axis
 * k), clear of it by at least {@value #MIN_GAP} of the largest coordinate. Every point X of the box
 * then projects to (u, v) = (X_a - L_a, X_b - L_b) / (s (X_k - L_k)), with a and b the other two
 * axes and s the side, and a segment in the box projects to the segment between its ends'
 * projections. The projected box is cut into a grid of cells about as large as a primitive's
 * projected bounding rectangle on average ({@link #CELL_SIZE}), and each cell lists every
 * primitive whose rectangle, widened by {@value #UV_MARGIN}, overlaps it, ordered by a lower bound
 * of the primitive's distance from the light (the distance to its bounding box, rounded down).
 *
 * <p>A ray can meet a primitive only inside the box (widened by {@value #BOX_PAD} of the largest
 * coordinate), so between its two faces across the depth axis; its piece there projects into the
 * rectangle of the piece's ends' projections,
 * widened by the same margin, and a primitive it meets is no farther from the light than the
 * piece's farther end. So testing the listed primitives of the cells under that rectangle, each
 * list up to the first bound beyond that end, with the primitives' own tests gives exactly the
 * answer of a BVH's any-hit search, for any ray: the margins exceed the rounding of the
 * projections and of the hit tests by a factor of about a million (docs/robustness.md, NUM-13). A
 * ray aimed at the light projects to a point, so one cell (up to four at a corner); a ray whose
 * piece covers more than {@value #MAX_QUERY_CELLS} cells is left to the tree. Each entry also keeps
 * the part of its cell that its primitive's rectangle covers, rounded outward to a grid of
 * {@value #SPAN_STEPS} steps a side ({@link #span}, four bytes), and a primitive whose part lies
 * clear of the piece's is not tested: a shadow ray aimed at the light tests a third as many
 * ({@code LightBufferTest}; kernel benchmark, mesh: 1.06 times the rays a second).
 *
 * <p>Building reads every primitive a few times; it asks a {@link MemoryGate} first for memory the
 * render can do without ({@link MemoryGate#tryReserve}) and gives up (no buffer) where that is not
 * free, or where the lists would hold more than {@value #MAX_ENTRIES_PER_PRIMITIVE} entries a
 * primitive. The peer benchmark's 104,000-triangle knot gets about 25,000 cells and 4 entries a
 * triangle per light.
 */
public final class LightBuffer {

    /** Whether primitive {@code item} lies on the ray with 0 &lt; t &lt; tMax: its owner's test of it. */
    @FunctionalInterface
    public interface Primitives {
        boolean occludes(int item, Ray ray, double tMax);
    }

    /** What {@link #occluder} returns when no listed primitive lies on the ray. */
    public static final int NONE = -1;
    /** What {@link #occluder} returns when the ray's piece covers too many cells: the tree decides. */
    public static final int UNDECIDED = -2;

    /**
     * A cell's side over the mean side of the primitives' projected rectangles. Smaller cells mean
     * shorter lists but more entries: half this size renders the peer mesh a little faster at 16
     * samples but costs more to build than it saves at one ({@code studio-bench peers}).
     */
    static final double CELL_SIZE = 1;
    /** The box must clear the light by this fraction of the largest coordinate. */
    static final double MIN_GAP = 1e-3;
    /** Projected coordinates of the box may reach this far (u = 16: 86 degrees off the depth axis). */
    static final double MAX_SLOPE = 16;
    /** Widening of every projected rectangle, in projected units. */
    static final double UV_MARGIN = 1e-7;
    /** The box is widened by this fraction of the largest coordinate before a ray is clipped to it. */
    static final double BOX_PAD = 1e-9;
    /** A ray whose piece in the box covers more cells than this is left to the tree. */
    static final int MAX_QUERY_CELLS = 4;
    /** Beyond this many list entries a primitive (plus one a cell) the buffer is not built. */
    static final int MAX_ENTRIES_PER_PRIMITIVE = 16;
    /** Lights a mesh or a scene keeps buffers for at most: each buffer costs building time and memory. */
    public static final int MAX_LIGHTS = 4;
    static final int MAX_CELLS = 1 << 22, MAX_SIDE = 4096;
    /** Steps a side of the grid inside a cell that an entry's rectangle is rounded outward to. */
    static final int SPAN_STEPS = 256;

    private final Primitives primitives;
    private final double lx, ly, lz;
    /** The depth axis, the two across it, and the side of the light the box is on (+1 or -1). */
    private final int depthAxis, uAxis, vAxis;
    private final double side;
    private final double u0, v0, cellsPerU, cellsPerV;
    private final int nu, nv;
    /** The box's faces across the depth axis, widened by {@link #BOX_PAD}. */
    private final double kLow, kHigh;
    /** Cell c lists entries [cellStart[c], cellStart[c + 1]). */
    private final int[] cellStart;
    /**
     * The entries, cell by cell, nearest the light first, three ints each (read together): the
     * primitive, its lower bound of distance from the light (a float's bits) and its rectangle
     * within the cell on a grid of {@value #SPAN_STEPS} steps a side ({@link #span}).
     */
    private final int[] entries;

    /** How the box is seen from the light: null where it is not clear on one side of it. */
    record Frame(double[] l, double[] box, int depth, double side, double uMin, double vMin,
                         double uMax, double vMax) {

        int uAxis() {
            return (depth + 1) % 3;
        }

        int vAxis() {
            return (depth + 2) % 3;
        }

        double z(double[] p, int o) {
            return side * (p[o + depth] - l[depth]);
        }

        static Frame of(Aabb b, Vec3 light) {
            double[] lo = {b.minX(), b.minY(), b.minZ()}, hi = {b.maxX(), b.maxY(), b.maxZ()};
            double[] l = {light.x(), light.y(), light.z()};
            double size = 0;
            for (int k = 0; k < 3; k++) {
                size = Math.max(size, Math.max(Math.max(Math.abs(lo[k]), Math.abs(hi[k])), Math.abs(l[k])));
            }
            if (!(size < Double.MAX_VALUE)) {
                return null;
            }
            double pad = BOX_PAD * size;
            for (int k = 0; k < 3; k++) {
                lo[k] -= pad;
                hi[k] += pad;
            }
            int depth = -1;
            double side = 0, gap = MIN_GAP * size;
            for (int k = 0; k < 3; k++) {
                if (lo[k] - l[k] >= gap) {
                    depth = k;
                    side = 1;
                    gap = lo[k] - l[k];
                }
                if (l[k] - hi[k] >= gap) {
                    depth = k;
                    side = -1;
                    gap = l[k] - hi[k];
                }
            }
            if (depth < 0) {
                return null;
            }
            double[] box = {lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]};
            double[] rect = new double[4];
            projectBox(box, 0, l, depth, side, rect, 0);
            double uMin = rect[0], uMax = rect[1], vMin = rect[2], vMax = rect[3];
            if (!(Math.max(Math.max(-uMin, uMax), Math.max(-vMin, vMax)) <= MAX_SLOPE)) {
                return null;
            }
            return new Frame(l, box, depth, side, uMin - UV_MARGIN, vMin - UV_MARGIN, uMax + UV_MARGIN,
                    vMax + UV_MARGIN);
        }
    }

    /**
     * The rectangle (uMin, uMax, vMin, vMax) of the eight corners of the box at {@code box[o ..]}
     * (min x, y, z, max x, y, z), projected from the light at l along axis {@code depth} on side
     * {@code side}, into {@code rect[at ..]}.
     */
    private static void projectBox(double[] box, int o, double[] l, int depth, double side, double[] rect, int at) {
        int ua = (depth + 1) % 3, va = (depth + 2) % 3;
        double uMin = Double.POSITIVE_INFINITY, uMax = Double.NEGATIVE_INFINITY, vMin = uMin, vMax = uMax;
        for (int c = 0; c < 8; c++) {
            double z = side * (box[o + depth + ((c & 4) == 0 ? 0 : 3)] - l[depth]);
            double u = (box[o + ua + ((c & 1) == 0 ? 0 : 3)] - l[ua]) / z;
            double v = (box[o + va + ((c & 2) == 0 ? 0 : 3)] - l[va]) / z;
            uMin = Math.min(uMin, u);
            uMax = Math.max(uMax, u);
            vMin = Math.min(vMin, v);
            vMax = Math.max(vMax, v);
        }
        rect[at] = uMin;
        rect[at + 1] = uMax;
        rect[at + 2] = vMin;
        rect[at + 3] = vMax;
    }

    LightBuffer(Frame f, Primitives primitives, int nu, int nv, int[] cellStart, int[] entries) {
        this.primitives = primitives;
        this.lx = f.l[0];
        this.ly = f.l[1];
        this.lz = f.l[2];
        this.depthAxis = f.depth;
        this.uAxis = f.uAxis();
        this.vAxis = f.vAxis();
        this.side = f.side;
        this.kLow = f.box[f.depth];
        this.kHigh = f.box[f.depth + 3];
        this.u0 = f.uMin;
        this.v0 = f.vMin;
        this.cellsPerU = nu / (f.uMax - f.uMin);
        this.cellsPerV = nv / (f.vMax - f.vMin);
        this.nu = nu;
        this.nv = nv;
        this.cellStart = cellStart;
        this.entries = entries;
    }

    /** A copy of {@code from} (its lists shared) that tests its primitives with {@code primitives}. */
    private LightBuffer(LightBuffer from, Primitives primitives) {
        this.primitives = primitives;
        this.lx = from.lx;
        this.ly = from.ly;
        this.lz = from.lz;
        this.depthAxis = from.depthAxis;
        this.uAxis = from.uAxis;
        this.vAxis = from.vAxis;
        this.side = from.side;
        this.kLow = from.kLow;
        this.kHigh = from.kHigh;
        this.u0 = from.u0;
        this.v0 = from.v0;
        this.cellsPerU = from.cellsPerU;
        this.cellsPerV = from.cellsPerV;
        this.nu = from.nu;
        this.nv = from.nv;
        this.cellStart = from.cellStart;
        this.entries = from.entries;
    }

    /**
     * This buffer, its lists shared, testing the listed primitives with {@code primitives}: for
     * primitives that stand where these did when it was built, as a scene whose objects but a few
     * are the same keeps it (the few are then tested beside it).
     */
    public LightBuffer testing(Primitives primitives) {
        return new LightBuffer(this, primitives);
    }

    /**
     * The buffer of a mesh's triangles (world positions {@code p}, 3 per vertex; vertex indices 3
     * per triangle, all inside {@code bounds}) for a light at {@code light}; null where the box does
     * not lie clear on one side of it, or the lists would grow too long. Each triangle's rectangle
     * is that of its three projected vertices.
     */
    static LightBuffer ofTriangles(double[] p, int[] indices, Aabb bounds, Vec3 light, Primitives triangles,
                                   MemoryGate memory) {
        Frame f = Frame.of(bounds, light);
        if (f == null) {
            return null;
        }
        int count = indices.length / 3, vertices = p.length / 3, ua = f.uAxis(), va = f.vAxis();
        if (!memory.tryReserve(2 * MemoryGate.doubles(vertices) + MemoryGate.doubles(4L * count)
                + MemoryGate.floats(count))) {
            return null;
        }
        double[] pu = new double[vertices], pv = new double[vertices];
        Runs.over(vertices, (from, to) -> {
            for (int i = from, o = 3 * from; i < to; i++, o += 3) {
                double z = f.z(p, o);
                pu[i] = (p[o + ua] - f.l[ua]) / z;
                pv[i] = (p[o + va] - f.l[va]) / z;
            }
        });
        double[] rects = new double[4 * count];
        float[] near = new float[count];
        double[] box = new double[6];
        Runs.over(count, (from, to) -> {
            for (int t = from; t < to; t++) {
                int a = indices[3 * t], b = indices[3 * t + 1], c = indices[3 * t + 2];
                rects[4 * t] = Math.min(pu[a], Math.min(pu[b], pu[c]));
                rects[4 * t + 1] = Math.max(pu[a], Math.max(pu[b], pu[c]));
                rects[4 * t + 2] = Math.min(pv[a], Math.min(pv[b], pv[c]));
                rects[4 * t + 3] = Math.max(pv[a], Math.max(pv[b], pv[c]));
                for (int k = 0; k < 3; k++) {
                    box[k] = Math.min(p[3 * a + k], Math.min(p[3 * b + k], p[3 * c + k]));
                    box[k + 3] = Math.max(p[3 * a + k], Math.max(p[3 * b + k], p[3 * c + k]));
                }
                near[t] = LightBufferLists.nearestBound(box, 0, f.l);
            }
        });
        return LightBufferLists.assemble(f, rects, near, triangles, memory);
    }

    /**
     * The buffer of boxed primitives (six doubles each: min x, y, z, max x, y, z; all inside
     * {@code bounds}) for a light at {@code light}; null as for {@link #ofTriangles}. Each
     * primitive's rectangle is that of its box's eight projected corners.
     */
    public static LightBuffer ofBoxes(double[] boxes, int count, Aabb bounds, Vec3 light, Primitives primitives,
                                      MemoryGate memory) {
        Frame f = Frame.of(bounds, light);
        if (f == null) {
            return null;
        }
        if (!memory.tryReserve(MemoryGate.doubles(4L * count) + MemoryGate.floats(count))) {
            return null;
        }
        double[] rects = new double[4 * count];
        float[] near = new float[count];
        Runs.over(count, (from, to) -> {
            for (int i = from; i < to; i++) {
                projectBox(boxes, 6 * i, f.l, f.depth, f.side, rects, 4 * i);
                near[i] = LightBufferLists.nearestBound(boxes, 6 * i, f.l);
            }
        });
        return LightBufferLists.assemble(f, rects, near, primitives, memory);
    }

    /** Whether the light this buffer sees from lies within {@code tolerance} of (x, y, z). */
    public boolean isAt(double x, double y, double z, double tolerance) {
        double dx = x - lx, dy = y - ly, dz = z - lz;
        return dx * dx + dy * dy + dz * dz <= tolerance * tolerance;
    }

    /**
     * A primitive that lies on the ray with 0 &lt; t &lt; tMax, or {@link #NONE}: whether there is
     * one is the tree's answer; {@link #UNDECIDED} when the ray's piece in the box covers too many
     * cells, for the tree to decide.
     */
    public int occluder(Ray ray, double tMax) {
        double ox = ray.ox, oy = ray.oy, oz = ray.oz, dx = ray.dx, dy = ray.dy, dz = ray.dz;
        // the piece between the box's two faces across the depth axis: it holds the piece in the box
        // (one division where clipping to all six faces took six)
        double ok = pick(depthAxis, ox, oy, oz), dk = pick(depthAxis, dx, dy, dz);
        double t0 = 0, t1 = tMax;
        if (dk != 0) {
            double inverse = 1 / dk, a = (kLow - ok) * inverse, b = (kHigh - ok) * inverse;
            t0 = Math.max(t0, Math.min(a, b));
            t1 = Math.min(t1, Math.max(a, b));
        } else if (!(ok >= kLow && ok <= kHigh)) {
            return NONE;
        }
        if (!(t0 <= t1)) {
            return t0 > t1 ? NONE : UNDECIDED; // the piece is empty; NaN (a ray that is not finite): the tree decides
        }
        // the piece's ends, from the light
        double ax = ox + t0 * dx - lx, ay = oy + t0 * dy - ly, az = oz + t0 * dz - lz;
        double bx = ox + t1 * dx - lx, by = oy + t1 * dy - ly, bz = oz + t1 * dz - lz;
        double za = side * pick(depthAxis, ax, ay, az), zb = side * pick(depthAxis, bx, by, bz);
        if (!(za > 0 && zb > 0)) {
            return UNDECIDED; // also where an end is not finite
        }
        double ia = 1 / za, ib = 1 / zb;
        double ua = pick(uAxis, ax, ay, az) * ia, va = pick(vAxis, ax, ay, az) * ia;
        double ub = pick(uAxis, bx, by, bz) * ib, vb = pick(vAxis, bx, by, bz) * ib;
        double iLow = (Math.min(ua, ub) - UV_MARGIN - u0) * cellsPerU;
        double iHigh = (Math.max(ua, ub) + UV_MARGIN - u0) * cellsPerU;
        double jLow = (Math.min(va, vb) - UV_MARGIN - v0) * cellsPerV;
        double jHigh = (Math.max(va, vb) + UV_MARGIN - v0) * cellsPerV;
        if (iHigh < 0 || jHigh < 0 || iLow >= nu || jLow >= nv) {
            return NONE; // outside every primitive's rectangle
        }
        if (!(iHigh - iLow < nu && jHigh - jLow < nv)) {
            return UNDECIDED;
        }
        int i0 = iLow < 0 ? 0 : (int) iLow, i1 = iHigh >= nu ? nu - 1 : (int) iHigh;
        int j0 = jLow < 0 ? 0 : (int) jLow, j1 = jHigh >= nv ? nv - 1 : (int) jHigh;
        if ((i1 - i0 + 1) * (j1 - j0 + 1) > MAX_QUERY_CELLS) {
            return UNDECIDED;
        }
        double reach = Math.sqrt(Math.max(ax * ax + ay * ay + az * az, bx * bx + by * by + bz * bz)) * (1 + 1e-6);
        for (int j = j0; j <= j1; j++) {
            int qv0 = step(jLow, j), qv1 = step(jHigh, j);
            for (int i = i0; i <= i1; i++) {
                int qu0 = step(iLow, i), qu1 = step(iHigh, i);
                int cell = j * nu + i;
                int[] list = entries;
                for (int e = 3 * cellStart[cell], end = 3 * cellStart[cell + 1];
                     e < end && Float.intBitsToFloat(list[e + 1]) <= reach; e += 3) {
                    int s = list[e + 2];
                    // the piece's rectangle and the entry's, both rounded outward in the cell, apart: skip it
                    if ((qu1 - (s & 0xFF) | ((s >>> 8) & 0xFF) - qu0 | qv1 - ((s >>> 16) & 0xFF) | (s >>> 24) - qv0) < 0) {
                        continue;
                    }
                    if (primitives.occludes(list[e], ray, tMax)) {
                        return list[e];
                    }
                }
            }
        }
        return NONE;
    }

    /**
     * The step of the grid inside cell {@code cell} (0 to {@value #SPAN_STEPS} - 1, clamped) that
     * holds x, a coordinate in cells along the same axis. Never decreasing in x, so that a
     * rectangle's lower and upper steps hold every point the rectangle does.
     */
    static int step(double x, int cell) {
        double s = (x - cell) * SPAN_STEPS;
        return s < 0 ? 0 : s >= SPAN_STEPS ? SPAN_STEPS - 1 : (int) s;
    }

    /** An entry's rectangle (lower and upper coordinates in cells) in cell (i, j), packed as {@link #occluder} reads it. */
    static int span(double uLow, double uHigh, double vLow, double vHigh, int i, int j) {
        return step(uLow, i) | step(uHigh, i) << 8 | step(vLow, j) << 16 | step(vHigh, j) << 24;
    }

    private static double pick(int axis, double x, double y, double z) {
        return axis == 0 ? x : axis == 1 ? y : z;
    }
}

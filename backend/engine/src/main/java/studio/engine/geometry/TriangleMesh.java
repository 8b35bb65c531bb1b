package studio.engine.geometry;

import java.util.Arrays;
import java.util.List;

import studio.engine.accel.Aabb;
import studio.engine.accel.Bvh;
import studio.engine.accel.Slab;
import studio.engine.math.Fp;
import studio.engine.math.Rotation;
import studio.engine.math.Vec3;
import studio.engine.memory.MemoryGate;
import studio.engine.mesh.MeshData;

/**
 * A triangle mesh placed in the world: an object-space {@link MeshData} moved to a position,
 * scaled uniformly and rotated (Euler degrees, order XYZ as three.js, like {@link Box}). The
 * vertices are transformed once, here, so rays are never transformed; the triangles sit in flat
 * arrays, ordered as the leaves of the mesh's own {@link Bvh}.
 *
 * <p>Rays meet triangles with the watertight test of Woop, Benthin and Wald (JCGT 2013): the axes
 * are permuted so the ray's largest direction component becomes z, the triangle is sheared so the
 * ray runs along z, and the three edge functions decide. The permutation and shear are worked out
 * once per ray ({@link Ray#shear}, shared by every mesh the ray meets); an edge shared by two triangles gives each of them exactly the negated edge
 * function, and edge functions of zero count as inside for both, so no ray slips through a shared
 * edge (robustness case NUM-08, docs/robustness.md). Like pbrt, a hit counts only if t exceeds its own rounding bound.
 *
 * <p>The reported normal is the geometric one, oriented by the winding (outward for
 * counter-clockwise triangles seen from outside, as in OBJ), or with vertex normals their
 * barycentric interpolation turned to the geometric normal's side. The hit point is the
 * barycentric combination of the vertices, with pbrt's error bound gamma(7)*sum|b_i*p_i|, so
 * {@link Rays#spawn} offsets it like any other hit, along the triangle's own (geometric) normal,
 * which the hit carries beside the interpolated one. Zero-area triangles are dropped when the mesh
 * is made. A shadow ray towards a light the mesh has a light buffer for ({@link #withLightBuffers})
 * tests the few triangles in its direction instead of searching the tree.
 *
 * <p>Making a mesh takes memory in proportion to it (its world-space copies, the triangles' boxes
 * and the BVH build, about 280 bytes a triangle in all); it is asked of a {@link MemoryGate} first.
 */
public final class TriangleMesh implements Shape {

    private static final double G2 = Fp.gamma(2), G3 = Fp.gamma(3), G5 = Fp.gamma(5), G7 = Fp.gamma(7);
    private static final LightBuffer[] NO_BUFFERS = {};

    private final MeshData source;
    private final Vec3 position, rotationDegrees;
    private final double scale;
    /** Rotated and scaled positions before the move to {@link #position}, 3 per vertex; shared by moved copies. */
    private final double[] unplaced;
    /** World positions, 3 per vertex: {@code position + unplaced}. */
    private final double[] positions;
    /** World unit normals, 3 per vertex, or null. */
    private final double[] normals;
    /** Texture coordinates, 2 per vertex (the mesh data's own array), or null. */
    private final double[] uvs;
    /** Vertex indices, 3 per triangle, in BVH leaf order; shared by moved copies. */
    private final int[] indices;
    /** The BVH's boxes, fitted to the world positions. */
    private final double[] nodeBounds;
    /** The BVH's links, shared by moved copies. */
    private final int[] nodeLinks;
    private final int nodeCount;
    private final Aabb bounds;
    private final long buildNanos;
    private final int bvhDepth;
    /** Whether the tree was built on the unplaced positions, so that a copy moved elsewhere may share it. */
    private final boolean movable;
    /** The lights this mesh was given buffers for, and the buffers of those that can have one ({@link #withLightBuffers}). */
    private final List<Vec3> bufferedLights;
    private final LightBuffer[] lightBuffers;

    public TriangleMesh(MeshData mesh, Vec3 position, double scale, Vec3 rotationDegrees) {
        this(mesh, position, scale, rotationDegrees, MemoryGate.UNLIMITED);
    }

    /**
     * As above, asking {@code memory} before every allocation that grows with the mesh.
     *
     * <p>The BVH is built on the rotated and scaled triangles before they are moved to
     * {@code position}, then its boxes are fitted to the moved ones; so the tree does not depend on
     * where the mesh stands, and {@link #movedTo} can move it without building the tree again,
     * giving the very mesh this constructor would. (If moving makes a triangle's area zero, which
     * only rounding far from the origin can, the tree is built on the moved triangles instead.)
     */
    public TriangleMesh(MeshData mesh, Vec3 position, double scale, Vec3 rotationDegrees, MemoryGate memory) {
        if (mesh == null) {
            throw new IllegalArgumentException("a triangle mesh needs mesh data");
        }
        if (position == null || !position.isFinite()) {
            throw new IllegalArgumentException("mesh position must be finite: " + position);
        }
        if (!(scale > 0) || !Double.isFinite(scale)) {
            throw new IllegalArgumentException("mesh scale must be positive and finite: " + scale);
        }
        if (rotationDegrees == null || !rotationDegrees.isFinite()) {
            throw new IllegalArgumentException("mesh rotation must be finite: " + rotationDegrees);
        }
        this.source = mesh;
        this.position = position;
        this.scale = scale;
        this.rotationDegrees = rotationDegrees;
        // At most every given triangle is kept: unplaced and world positions, normals, the kept
        // indices (and their trimmed copy), the boxes and the indices in BVH order; the BVH asks for
        // its own.
        long given = mesh.indices().length;
        memory.reserve(2 * MemoryGate.doubles(mesh.positions().length)
                + (mesh.normals() == null ? 0 : MemoryGate.doubles(mesh.normals().length))
                + 3 * MemoryGate.ints(given) + MemoryGate.doubles(2 * given));
        Rotation r = Rotation.fromEulerDegrees(rotationDegrees);
        this.unplaced = unplacedPositions(mesh.positions(), r, scale);
        this.positions = moved(unplaced, position);
        this.normals = mesh.normals() == null ? null : worldNormals(mesh.normals(), r);
        this.uvs = mesh.uvs();
        int[] valid = nonDegenerate(mesh.indices(), unplaced);
        boolean movable = haveArea(valid, positions);
        if (!movable) {
            valid = nonDegenerate(mesh.indices(), positions);
        }
        int count = valid.length / 3;
        if (count == 0) {
            throw new IllegalArgumentException("mesh has no triangle with non-zero area ("
                    + mesh.triangleCount() + " given)");
        }
        double[] tree = movable ? unplaced : positions;
        double[] boxes = new double[6 * count];
        for (int t = 0; t < count; t++) {
            triangleBounds(tree, valid, t, boxes);
        }
        Bvh bvh = Bvh.build(boxes, count, memory);
        int[] order = bvh.primitives();
        int[] sorted = new int[valid.length];
        for (int slot = 0; slot < count; slot++) {
            System.arraycopy(valid, 3 * order[slot], sorted, 3 * slot, 3);
        }
        this.movable = movable;
        this.indices = sorted;
        this.nodeLinks = bvh.nodes();
        this.nodeCount = bvh.nodeCount();
        if (movable) {
            memory.reserve(MemoryGate.doubles(6L * nodeCount));
        }
        this.nodeBounds = movable ? fitted(positions, sorted, nodeLinks, nodeCount) : bvh.bounds();
        this.bounds = rootBounds(nodeBounds);
        this.buildNanos = bvh.buildNanos();
        this.bvhDepth = bvh.depth();
        this.bufferedLights = List.of();
        this.lightBuffers = NO_BUFFERS;
    }

    /** The mesh as it is, at the origin, unscaled and unrotated. */
    public TriangleMesh(MeshData mesh) {
        this(mesh, Vec3.ZERO, 1, Vec3.ZERO);
    }

    /**
     * A copy of {@code from} sharing its triangles and tree, at {@code position} with these world
     * positions and boxes, and these light buffers: a moved copy ({@link #movedTo}) or one with
     * buffers ({@link #withLightBuffers}).
     */
    private TriangleMesh(TriangleMesh from, Vec3 position, double[] positions, double[] nodeBounds, long buildNanos,
                         List<Vec3> bufferedLights, LightBuffer[] lightBuffers) {
        this.source = from.source;
        this.position = position;
        this.scale = from.scale;
        this.rotationDegrees = from.rotationDegrees;
        this.unplaced = from.unplaced;
        this.positions = positions;
        this.normals = from.normals;
        this.uvs = from.uvs;
        this.indices = from.indices;
        this.nodeLinks = from.nodeLinks;
        this.nodeCount = from.nodeCount;
        this.nodeBounds = nodeBounds;
        this.bounds = rootBounds(nodeBounds);
        this.buildNanos = buildNanos;
        this.bvhDepth = from.bvhDepth;
        this.movable = from.movable;
        this.bufferedLights = bufferedLights;
        this.lightBuffers = lightBuffers;
    }

    /**
     * This mesh with a light buffer ({@link LightBuffer}) for each of the first
     * {@value LightBuffer#MAX_LIGHTS} of these point lights that can have one (its box clear of the
     * light on one side): a shadow ray that ends at such a light tests the few triangles in its
     * direction instead of searching the tree, with the same answer. The peer benchmark's mesh
     * rendered in about 0.7 of the time warm (1.26 s against 1.75-1.76), and whole processes in
     * 0.84 at 16 samples; which renders
     * pay for the building is {@code MeshLightBuffers}' rule. Itself if it already has buffers for
     * exactly these lights; each buffer keeps some 35 bytes a triangle (and takes about 70 more
     * while it is built), asked of {@code memory} first. A moved copy ({@link #movedTo}) has none.
     */
    public TriangleMesh withLightBuffers(List<Vec3> lights, MemoryGate memory) {
        if (lights.equals(bufferedLights)) {
            return this;
        }
        int n = Math.min(lights.size(), LightBuffer.MAX_LIGHTS);
        LightBuffer[] buffers = new LightBuffer[n];
        int built = 0;
        for (int i = 0; i < n; i++) {
            LightBuffer buffer = LightBuffer.ofTriangles(positions, indices, bounds, lights.get(i), this::occludedBy,
                    memory);
            if (buffer != null) {
                buffers[built++] = buffer;
            }
        }
        return new TriangleMesh(this, position, positions, nodeBounds, buildNanos, List.copyOf(lights),
                Arrays.copyOf(buffers, built));
    }

    /** How many light buffers this mesh has. */
    public int lightBufferCount() {
        return lightBuffers.length;
    }

    /**
     * This mesh with its position changed to {@code position}: the same mesh as the constructor
     * makes for the same data, scale, rotation and that position, made without building its BVH
     * again (the tree is shared, only its boxes are fitted to the moved triangles): about 3 ms
     * instead of 31 for 50,000 triangles. What the live view does when an edit moves a mesh.
     */
    public TriangleMesh movedTo(Vec3 position, MemoryGate memory) {
        if (position == null || !position.isFinite()) {
            throw new IllegalArgumentException("mesh position must be finite: " + position);
        }
        if (!movable) {
            return new TriangleMesh(source, position, scale, rotationDegrees, memory);
        }
        memory.reserve(MemoryGate.doubles(unplaced.length) + MemoryGate.doubles(nodeBounds.length));
        double[] world = moved(unplaced, position);
        if (!haveArea(indices, world)) {
            return new TriangleMesh(source, position, scale, rotationDegrees, memory);
        }
        return new TriangleMesh(this, position, world, fitted(world, indices, nodeLinks, nodeCount), 0, List.of(),
                NO_BUFFERS);
    }

    /** The positions rotated and scaled, not yet moved. */
    private static double[] unplacedPositions(double[] object, Rotation r, double scale) {
        double m00 = r.get(0, 0), m01 = r.get(0, 1), m02 = r.get(0, 2);
        double m10 = r.get(1, 0), m11 = r.get(1, 1), m12 = r.get(1, 2);
        double m20 = r.get(2, 0), m21 = r.get(2, 1), m22 = r.get(2, 2);
        double[] rotated = new double[object.length];
        for (int i = 0; i < object.length; i += 3) {
            double x = scale * object[i], y = scale * object[i + 1], z = scale * object[i + 2];
            rotated[i] = m00 * x + m01 * y + m02 * z;
            rotated[i + 1] = m10 * x + m11 * y + m12 * z;
            rotated[i + 2] = m20 * x + m21 * y + m22 * z;
        }
        return rotated;
    }

    /** The unplaced positions moved to {@code position}. */
    private static double[] moved(double[] unplaced, Vec3 position) {
        double tx = position.x(), ty = position.y(), tz = position.z();
        double[] world = new double[unplaced.length];
        for (int i = 0; i < unplaced.length; i += 3) {
            world[i] = tx + unplaced[i];
            world[i + 1] = ty + unplaced[i + 1];
            world[i + 2] = tz + unplaced[i + 2];
            if (!Double.isFinite(world[i]) || !Double.isFinite(world[i + 1]) || !Double.isFinite(world[i + 2])) {
                throw new IllegalArgumentException("vertex " + i / 3 + " is not finite once placed in the world");
            }
        }
        return world;
    }

    /**
     * The BVH's boxes for these positions: each leaf's the exact bounds of its triangles, each
     * interior node's the union of its children's (children come after their parent, so one pass
     * from the last node back).
     */
    private static double[] fitted(double[] p, int[] indices, int[] links, int nodeCount) {
        double[] b = new double[6 * nodeCount];
        for (int node = nodeCount - 1; node >= 0; node--) {
            int o = 3 * node, k = 6 * node;
            int count = links[o + 1];
            if (count >= 0) {
                for (int axis = 0; axis < 3; axis++) {
                    double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
                    for (int i = 3 * links[o], end = 3 * (links[o] + count); i < end; i++) {
                        double v = p[3 * indices[i] + axis];
                        lo = Math.min(lo, v);
                        hi = Math.max(hi, v);
                    }
                    b[k + axis] = lo;
                    b[k + 3 + axis] = hi;
                }
            } else {
                int left = 6 * (node + 1), right = 6 * links[o];
                for (int axis = 0; axis < 3; axis++) {
                    b[k + axis] = Math.min(b[left + axis], b[right + axis]);
                    b[k + 3 + axis] = Math.max(b[left + 3 + axis], b[right + 3 + axis]);
                }
            }
        }
        return b;
    }

    private static Aabb rootBounds(double[] b) {
        return new Aabb(b[0], b[1], b[2], b[3], b[4], b[5]);
    }

    private static double[] worldNormals(double[] object, Rotation r) {
        double[] world = new double[object.length];
        for (int i = 0; i < object.length; i += 3) {
            Vec3 n = r.apply(new Vec3(object[i], object[i + 1], object[i + 2])).normalized();
            world[i] = n.x();
            world[i + 1] = n.y();
            world[i + 2] = n.z();
        }
        return world;
    }

    /** The triangles whose cross product at these positions is non-zero, in their given order. */
    private static int[] nonDegenerate(int[] indices, double[] p) {
        int[] kept = new int[indices.length];
        int n = 0;
        for (int i = 0; i < indices.length; i += 3) {
            if (hasArea(indices, i, p)) {
                kept[n++] = indices[i];
                kept[n++] = indices[i + 1];
                kept[n++] = indices[i + 2];
            }
        }
        return n == kept.length ? kept : Arrays.copyOf(kept, n);
    }

    /** Whether every triangle's cross product at these positions is non-zero. */
    private static boolean haveArea(int[] indices, double[] p) {
        for (int i = 0; i < indices.length; i += 3) {
            if (!hasArea(indices, i, p)) {
                return false;
            }
        }
        return true;
    }

    private static boolean hasArea(int[] indices, int i, double[] p) {
        int a = 3 * indices[i], b = 3 * indices[i + 1], c = 3 * indices[i + 2];
        double ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
        double vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
        double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
        return (cx != 0 || cy != 0 || cz != 0) && Double.isFinite(cx) && Double.isFinite(cy) && Double.isFinite(cz);
    }

    private static void triangleBounds(double[] positions, int[] tris, int t, double[] out) {
        int a = 3 * tris[3 * t], b = 3 * tris[3 * t + 1], c = 3 * tris[3 * t + 2];
        for (int k = 0; k < 3; k++) {
            double pa = positions[a + k], pb = positions[b + k], pc = positions[c + k];
            out[6 * t + k] = Math.min(pa, Math.min(pb, pc));
            out[6 * t + 3 + k] = Math.max(pa, Math.max(pb, pc));
        }
    }

    @Override
    public boolean intersect(Ray ray, double tMax, Hit hit) {
        double dx = ray.dx, dy = ray.dy, dz = ray.dz;
        RayShear f = ray.shear();
        int kx = f.kx, ky = f.ky, kz = f.kz;
        double sx = f.sx, sy = f.sy, sz = f.sz, okx = f.okx, oky = f.oky, okz = f.okz;
        double ox = ray.ox, oy = ray.oy, oz = ray.oz;
        double ix = 1 / dx, iy = 1 / dy, iz = 1 / dz;
        boolean nanFree = Slab.nanFree(ox, oy, oz, ix, iy, iz);

        double[] nb = nodeBounds;
        int[] links = nodeLinks;
        int[] stack = hit.shapeStack;
        double[] stackEntry = hit.shapeStackEntry;
        int sp = 0, node = 0, bestTri = -1;
        double best = tMax;
        double entry = Slab.entry(nb, 0, ox, oy, oz, ix, iy, iz, nanFree, best);
        while (true) {
            if (entry <= best) { // a miss is NaN: false
                int o = 3 * node;
                int count = links[o + 1];
                if (count < 0) {
                    // the scene's order (ShapeSet): both children's boxes tested here, the nearer visited
                    // first, the other kept with its entry distance, one the ray misses never pushed
                    int left = node + 1, right = links[o];
                    double inLeft = Slab.entry(nb, 6 * left, ox, oy, oz, ix, iy, iz, nanFree, best);
                    double inRight = Slab.entry(nb, 6 * right, ox, oy, oz, ix, iy, iz, nanFree, best);
                    boolean hitLeft = inLeft <= best, hitRight = inRight <= best;
                    if (hitLeft && hitRight) {
                        boolean leftFirst = inLeft <= inRight;
                        stack[sp] = leftFirst ? right : left;
                        stackEntry[sp++] = leftFirst ? inRight : inLeft;
                        node = leftFirst ? left : right;
                        entry = leftFirst ? inLeft : inRight;
                        continue;
                    }
                    if (hitLeft || hitRight) {
                        node = hitLeft ? left : right;
                        entry = hitLeft ? inLeft : inRight;
                        continue;
                    }
                } else {
                    for (int tri = links[o], end = tri + count; tri < end; tri++) {
                        double t = distance(tri, okx, oky, okz, kx, ky, kz, sx, sy, sz, best);
                        if (t == t) {
                            best = t;
                            bestTri = tri;
                        }
                    }
                }
            }
            if (sp == 0) {
                break;
            }
            node = stack[--sp];
            entry = stackEntry[sp];
        }
        if (bestTri < 0) {
            return false;
        }
        fill(bestTri, okx, oky, okz, kx, ky, kz, sx, sy, sz, hit);
        return true;
    }

    @Override
    public boolean occluded(Ray ray, double tMax) {
        double dx = ray.dx, dy = ray.dy, dz = ray.dz;
        RayShear f = ray.shear();
        int kx = f.kx, ky = f.ky, kz = f.kz;
        double sx = f.sx, sy = f.sy, sz = f.sz, okx = f.okx, oky = f.oky, okz = f.okz;
        double ox = ray.ox, oy = ray.oy, oz = ray.oz;
        double ix = 1 / dx, iy = 1 / dy, iz = 1 / dz;
        LightBuffer[] buffers = lightBuffers;
        if (buffers.length > 0) {
            // a shadow ray ends within a millionth of its length of its light (Integrator: 1e-9 short)
            double ex = ox + dx * tMax, ey = oy + dy * tMax, ez = oz + dz * tMax, tolerance = 1e-6 * tMax;
            for (LightBuffer buffer : buffers) {
                if (buffer.isAt(ex, ey, ez, tolerance)) {
                    int occluder = buffer.occluder(ray, tMax);
                    if (occluder != LightBuffer.UNDECIDED) {
                        return occluder >= 0;
                    }
                    break;
                }
            }
        }
        boolean nanFree = Slab.nanFree(ox, oy, oz, ix, iy, iz);

        // Any hit will do, so no order and no stack: a missed node, or a finished leaf, escapes
        // to the node after its subtree.
        double[] nb = nodeBounds;
        int[] links = nodeLinks;
        int node = 0, end = nodeCount;
        while (node < end) {
            int o = 3 * node;
            if (Slab.hits(nb, 6 * node, ox, oy, oz, ix, iy, iz, nanFree, tMax)) {
                int count = links[o + 1];
                if (count < 0) {
                    node++;
                    continue;
                }
                for (int tri = links[o], last = tri + count; tri < last; tri++) {
                    double t = distance(tri, okx, oky, okz, kx, ky, kz, sx, sy, sz, tMax);
                    if (t == t) {
                        return true;
                    }
                }
            }
            node = links[o + 2];
        }
        return false;
    }

    /** Whether triangle {@code tri} lies on the ray with 0 &lt; t &lt; tMax (a light buffer's test). */
    boolean occludedBy(int tri, Ray ray, double tMax) {
        RayShear f = ray.shear();
        double t = distance(tri, f.okx, f.oky, f.okz, f.kx, f.ky, f.kz, f.sx, f.sy, f.sz, tMax);
        return t == t;
    }

    /**
     * The nearest hit by testing every triangle, without the BVH: the reference the BVH is
     * checked against (tests, robustness case NUM-06, docs/robustness.md).
     */
    boolean intersectEachTriangle(Ray ray, double tMax, Hit hit) {
        RayShear f = ray.shear();
        int kx = f.kx, ky = f.ky, kz = f.kz;
        double sx = f.sx, sy = f.sy, sz = f.sz, okx = f.okx, oky = f.oky, okz = f.okz;
        double best = tMax;
        int bestTri = -1;
        for (int tri = 0; tri < indices.length / 3; tri++) {
            double t = distance(tri, okx, oky, okz, kx, ky, kz, sx, sy, sz, best);
            if (t == t) {
                best = t;
                bestTri = tri;
            }
        }
        if (bestTri < 0) {
            return false;
        }
        fill(bestTri, okx, oky, okz, kx, ky, kz, sx, sy, sz, hit);
        return true;
    }

    /**
     * The watertight test of one triangle against the permuted and sheared ray: its distance if
     * 0 &lt; t &lt; tMax and t exceeds its rounding bound, else NaN.
     */
    private double distance(int tri, double okx, double oky, double okz, int kx, int ky, int kz,
                            double sx, double sy, double sz, double tMax) {
        double[] p = positions;
        int a = 3 * indices[3 * tri], b = 3 * indices[3 * tri + 1], c = 3 * indices[3 * tri + 2];
        double z0 = p[a + kz] - okz, z1 = p[b + kz] - okz, z2 = p[c + kz] - okz;
        double x0 = p[a + kx] - okx + sx * z0, y0 = p[a + ky] - oky + sy * z0;
        double x1 = p[b + kx] - okx + sx * z1, y1 = p[b + ky] - oky + sy * z1;
        double x2 = p[c + kx] - okx + sx * z2, y2 = p[c + ky] - oky + sy * z2;
        double e0 = x1 * y2 - y1 * x2, e1 = x2 * y0 - y2 * x0, e2 = x0 * y1 - y0 * x1;
        if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) {
            return Double.NaN;
        }
        double det = e0 + e1 + e2;
        if (det == 0) {
            return Double.NaN;
        }
        z0 *= sz;
        z1 *= sz;
        z2 *= sz;
        double tScaled = e0 * z0 + e1 * z1 + e2 * z2;
        if (det < 0 ? tScaled >= 0 || tScaled < tMax * det : tScaled <= 0 || tScaled > tMax * det) {
            return Double.NaN;
        }
        double invDet = 1 / det;
        double t = tScaled * invDet;
        if (!(t > 0 && t < tMax)) {
            return Double.NaN;
        }
        // pbrt-v3 3.9.6: t must exceed the bound on its own rounding error.
        double maxZ = Math.max(Math.abs(z0), Math.max(Math.abs(z1), Math.abs(z2)));
        double maxX = Math.max(Math.abs(x0), Math.max(Math.abs(x1), Math.abs(x2)));
        double maxY = Math.max(Math.abs(y0), Math.max(Math.abs(y1), Math.abs(y2)));
        double deltaX = G5 * (maxX + maxZ), deltaY = G5 * (maxY + maxZ), deltaZ = G3 * maxZ;
        double deltaE = 2 * (G2 * maxX * maxY + deltaY * maxX + deltaX * maxY);
        double maxE = Math.max(Math.abs(e0), Math.max(Math.abs(e1), Math.abs(e2)));
        double deltaT = 3 * (G3 * maxE * maxZ + deltaE * maxZ + deltaZ * maxE) * Math.abs(invDet);
        return t > deltaT ? t : Double.NaN;
    }

    /** Fills the hit record for a triangle {@link #distance} accepted: same arithmetic, so the same t. */
    private void fill(int tri, double okx, double oky, double okz, int kx, int ky, int kz,
                      double sx, double sy, double sz, Hit hit) {
        double[] p = positions;
        int ia = indices[3 * tri], ib = indices[3 * tri + 1], ic = indices[3 * tri + 2];
        int a = 3 * ia, b = 3 * ib, c = 3 * ic;
        double z0 = p[a + kz] - okz, z1 = p[b + kz] - okz, z2 = p[c + kz] - okz;
        double x0 = p[a + kx] - okx + sx * z0, y0 = p[a + ky] - oky + sy * z0;
        double x1 = p[b + kx] - okx + sx * z1, y1 = p[b + ky] - oky + sy * z1;
        double x2 = p[c + kx] - okx + sx * z2, y2 = p[c + ky] - oky + sy * z2;
        double e0 = x1 * y2 - y1 * x2, e1 = x2 * y0 - y2 * x0, e2 = x0 * y1 - y0 * x1;
        double invDet = 1 / (e0 + e1 + e2);
        double t = (e0 * (z0 * sz) + e1 * (z1 * sz) + e2 * (z2 * sz)) * invDet;
        double b0 = e0 * invDet, b1 = e1 * invDet, b2 = e2 * invDet;

        double px = b0 * p[a] + b1 * p[b] + b2 * p[c];
        double py = b0 * p[a + 1] + b1 * p[b + 1] + b2 * p[c + 1];
        double pz = b0 * p[a + 2] + b1 * p[b + 2] + b2 * p[c + 2];
        double ex = G7 * (Math.abs(b0 * p[a]) + Math.abs(b1 * p[b]) + Math.abs(b2 * p[c]));
        double ey = G7 * (Math.abs(b0 * p[a + 1]) + Math.abs(b1 * p[b + 1]) + Math.abs(b2 * p[c + 1]));
        double ez = G7 * (Math.abs(b0 * p[a + 2]) + Math.abs(b1 * p[b + 2]) + Math.abs(b2 * p[c + 2]));

        double ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
        double vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
        double gx = uy * vz - uz * vy, gy = uz * vx - ux * vz, gz = ux * vy - uy * vx;
        double gm = Math.max(Math.abs(gx), Math.max(Math.abs(gy), Math.abs(gz)));
        gx /= gm; gy /= gm; gz /= gm;
        double gl = Math.sqrt(gx * gx + gy * gy + gz * gz);
        gx /= gl;
        gy /= gl;
        gz /= gl;
        double nx = gx, ny = gy, nz = gz;
        if (normals != null) {
            double[] n = normals;
            double sxn = b0 * n[a] + b1 * n[b] + b2 * n[c];
            double syn = b0 * n[a + 1] + b1 * n[b + 1] + b2 * n[c + 1];
            double szn = b0 * n[a + 2] + b1 * n[b + 2] + b2 * n[c + 2];
            double sl = Math.sqrt(sxn * sxn + syn * syn + szn * szn);
            if (sl > 0 && Double.isFinite(sl)) {
                double flip = sxn * nx + syn * ny + szn * nz < 0 ? -1 / sl : 1 / sl;
                nx = sxn * flip;
                ny = syn * flip;
                nz = szn * flip;
            }
        }
        hit.set(t, px, py, pz, nx, ny, nz, gx, gy, gz, ex, ey, ez);
        hit.triangle = tri;
        hit.b1 = b1;
        hit.b2 = b2;
    }

    /**
     * The hit triangle's vertex UVs interpolated by its barycentrics, and dp/du, dp/dv solved from its
     * edges (pbrt's Triangle::Intersect); without UVs the barycentrics themselves (the vertices at
     * (0, 0), (1, 0) and (0, 1)). A triangle whose UVs have no area has dp/du = dp/dv = 0: its
     * footprint covers the whole texture.
     */
    @Override
    public void textureCoordinates(Hit hit, TextureCoordinates out) {
        double[] p = positions;
        int tri = hit.triangle;
        int ia = indices[3 * tri], ib = indices[3 * tri + 1], ic = indices[3 * tri + 2];
        int a = 3 * ia, b = 3 * ib, c = 3 * ic;
        double b1 = hit.b1, b2 = hit.b2, b0 = 1 - b1 - b2;
        if (uvs == null) {
            out.set(b1, b2, p[b] - p[a], p[b + 1] - p[a + 1], p[b + 2] - p[a + 2],
                    p[c] - p[a], p[c + 1] - p[a + 1], p[c + 2] - p[a + 2], 1, 1, false);
            return;
        }
        double[] t = uvs;
        double u0 = t[2 * ia], v0 = t[2 * ia + 1], u1 = t[2 * ib], v1 = t[2 * ib + 1], u2 = t[2 * ic], v2 = t[2 * ic + 1];
        double du02 = u0 - u2, dv02 = v0 - v2, du12 = u1 - u2, dv12 = v1 - v2;
        double det = du02 * dv12 - dv02 * du12;
        double ux = 0, uy = 0, uz = 0, vx = 0, vy = 0, vz = 0;
        if (det != 0 && Double.isFinite(1 / det)) {
            double inv = 1 / det;
            double x02 = p[a] - p[c], y02 = p[a + 1] - p[c + 1], z02 = p[a + 2] - p[c + 2];
            double x12 = p[b] - p[c], y12 = p[b + 1] - p[c + 1], z12 = p[b + 2] - p[c + 2];
            ux = (dv12 * x02 - dv02 * x12) * inv;
            uy = (dv12 * y02 - dv02 * y12) * inv;
            uz = (dv12 * z02 - dv02 * z12) * inv;
            vx = (du02 * x12 - du12 * x02) * inv;
            vy = (du02 * y12 - du12 * y02) * inv;
            vz = (du02 * z12 - du12 * z02) * inv;
        }
        out.set(b0 * u0 + b1 * u1 + b2 * u2, b0 * v0 + b1 * v1 + b2 * v2, ux, uy, uz, vx, vy, vz, 1, 1, false);
    }

    /** Whether the mesh carries texture coordinates. */
    public boolean hasUvs() {
        return uvs != null;
    }

    @Override
    public Aabb bounds() {
        return bounds;
    }

    public int triangleCount() {
        return indices.length / 3;
    }

    public int vertexCount() {
        return positions.length / 3;
    }

    /** World-space vertex positions, 3 per vertex (a copy). */
    public double[] positions() {
        return positions.clone();
    }

    /** Vertex indices, 3 per triangle, counter-clockwise seen from outside (a copy; zero-area triangles dropped). */
    public int[] indices() {
        return indices.clone();
    }

    /** World-space unit vertex normals, 3 per vertex (a copy), or null for a flat-shaded mesh. */
    public double[] normals() {
        return normals == null ? null : normals.clone();
    }

    public Vec3 position() {
        return position;
    }

    public double scale() {
        return scale;
    }

    public Vec3 rotationDegrees() {
        return rotationDegrees;
    }

    /** How long building the triangles' BVH took. */
    public long buildNanos() {
        return buildNanos;
    }

    /** Levels of the triangles' BVH. */
    public int bvhDepth() {
        return bvhDepth;
    }

    @Override
    public String toString() {
        return "TriangleMesh[triangles=" + triangleCount() + ", position=" + position + ", scale=" + scale
                + ", rotationDegrees=" + rotationDegrees + "]";
    }
}

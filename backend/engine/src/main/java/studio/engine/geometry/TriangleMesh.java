package studio.engine.geometry;

import java.util.Arrays;
import java.util.List;

import studio.engine.accel.Aabb;
import studio.engine.accel.Bvh;
import studio.engine.accel.Traversal;
import studio.engine.accel.TriangleLeaves;
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
 * <p>Rays meet triangles with the watertight test ({@link TriangleLeaves}), through the engine's
 * one BVH walk ({@link Traversal}).
 *
 * <p>The reported normal is the geometric one, oriented by the winding (outward for
 * counter-clockwise triangles seen from outside, as in OBJ), or with vertex normals their
 * interpolation turned to its side; the hit record is worked out once, for the winning triangle
 * ({@link TriangleHits}). Zero-area triangles are dropped when the mesh
 * is made. A shadow ray towards a light the mesh has a light buffer for ({@link #withLightBuffers})
 * tests the few triangles in its direction instead of searching the tree.
 *
 * <p>Making a mesh takes memory in proportion to it (its world-space copies, the triangles' boxes
 * and the BVH build, about 280 bytes a triangle in all); it is asked of a {@link MemoryGate} first.
 */
public final class TriangleMesh implements Shape {

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
    /** The triangles over the world positions, and the walk of the tree over them. */
    private final TriangleLeaves leaves;
    private final Traversal traversal;
    /** The BVH's links, shared by moved copies. */
    private final int[] nodeLinks;
    private final int nodeCount;
    private final Aabb bounds;
    private final long buildNanos;
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
        this.unplaced = MeshPlacement.unplacedPositions(mesh.positions(), r, scale);
        this.positions = MeshPlacement.moved(unplaced, position);
        this.normals = mesh.normals() == null ? null : MeshPlacement.worldNormals(mesh.normals(), r);
        this.uvs = mesh.uvs();
        int[] valid = MeshPlacement.nonDegenerate(mesh.indices(), unplaced);
        boolean movable = MeshPlacement.haveArea(valid, positions);
        if (!movable) {
            valid = MeshPlacement.nonDegenerate(mesh.indices(), positions);
        }
        int count = valid.length / 3;
        if (count == 0) {
            throw new IllegalArgumentException("mesh has no triangle with non-zero area ("
                    + mesh.triangleCount() + " given)");
        }
        double[] tree = movable ? unplaced : positions;
        double[] boxes = new double[6 * count];
        for (int t = 0; t < count; t++) {
            MeshPlacement.triangleBounds(tree, valid, t, boxes);
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
        this.nodeBounds = movable ? MeshPlacement.fitted(positions, sorted, nodeLinks, nodeCount) : bvh.bounds();
        this.leaves = new TriangleLeaves(positions, sorted);
        this.traversal = new Traversal(nodeBounds, nodeLinks, leaves, memory);
        this.bounds = MeshPlacement.rootBounds(nodeBounds);
        this.buildNanos = bvh.buildNanos();
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
        this.leaves = positions == from.positions ? from.leaves : new TriangleLeaves(positions, indices);
        this.traversal = nodeBounds == from.nodeBounds ? from.traversal : new Traversal(nodeBounds, nodeLinks, leaves);
        this.bounds = MeshPlacement.rootBounds(nodeBounds);
        this.buildNanos = buildNanos;
        this.movable = from.movable;
        this.bufferedLights = bufferedLights;
        this.lightBuffers = lightBuffers;
    }

    /**
     * This mesh with a light buffer ({@link LightBuffer}) for each of the first
     * {@value LightBuffer#MAX_LIGHTS} of these point lights that can have one (its box clear of the
     * light on one side): a shadow ray that ends at such a light tests the few triangles in its
     * direction instead of searching the tree, with the same answer: the peer benchmark's mesh
     * renders in about 0.7 of the time warm and 0.84 as whole processes at 16 samples
     * ({@code studio-bench peers}); which renders
     * pay for the building is {@code MeshLightBuffers}' rule. Itself if it already has buffers for
     * exactly these lights; each buffer keeps some 50 bytes a triangle (and takes about 70 more
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
        double[] world = MeshPlacement.moved(unplaced, position);
        if (!MeshPlacement.haveArea(indices, world)) {
            return new TriangleMesh(source, position, scale, rotationDegrees, memory);
        }
        return new TriangleMesh(this, position, world, MeshPlacement.fitted(world, indices, nodeLinks, nodeCount), 0, List.of(),
                NO_BUFFERS);
    }

    @Override
    public boolean intersect(Ray ray, double tMax, Hit hit) {
        double best = traversal.nearest(ray, tMax, tMax, hit, hit.shapeStack, hit.shapeStackEntry, hit.shapeWide);
        if (!(best < tMax)) {
            return false;
        }
        fill(hit.triangle, ray.shear(), hit);
        return true;
    }

    @Override
    public boolean occluded(Ray ray, double tMax) {
        LightBuffer[] buffers = lightBuffers;
        if (buffers.length > 0) {
            // a shadow ray ends within a millionth of its length of its light (Integrator: 1e-9 short)
            double ex = ray.ox + ray.dx * tMax, ey = ray.oy + ray.dy * tMax, ez = ray.oz + ray.dz * tMax;
            double tolerance = 1e-6 * tMax;
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
        return traversal.any(ray, tMax, ray.shapeWide());
    }

    /** Whether triangle {@code tri} lies on the ray with 0 &lt; t &lt; tMax (a light buffer's test). */
    boolean occludedBy(int tri, Ray ray, double tMax) {
        return leaves.any(tri, tri + 1, ray, tMax);
    }

    /** Fills the hit record for a triangle {@link TriangleLeaves#distance} accepted. */
    private void fill(int tri, RayShear f, Hit hit) {
        TriangleHits.fill(positions, normals, indices, tri, f, hit);
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

    /** {@inheritDoc} Here: a mesh may be any shape; its triangles are not asked one by one. */
    @Override
    public boolean convex() {
        return false;
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

    @Override
    public String toString() {
        return "TriangleMesh[triangles=" + triangleCount() + ", position=" + position + ", scale=" + scale
                + ", rotationDegrees=" + rotationDegrees + "]";
    }
}

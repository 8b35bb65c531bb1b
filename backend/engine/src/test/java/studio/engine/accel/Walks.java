package studio.engine.accel;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Shape;
import studio.engine.memory.MemoryGate;

/**
 * The engine's one {@link Traversal} over a tree of shapes or of triangles, made to walk one way
 * whatever this JVM would choose: the binary tree, or the wide one with this JVM's box test
 * ({@link WideBoxTests#get}; {@code studio.vector=off} makes it the scalar one). Tests hold the two
 * walks to the same hits; the wide BVH benchmark times them. One per thread: it holds the walk's
 * hit record, stack and wide scratch.
 */
public final class Walks {

    private final Bvh bvh;
    private final Leaves leaves;
    private final int[] stack = new int[Bvh.STACK_SIZE];
    private final double[] stackEntry = new double[Bvh.STACK_SIZE];
    private final WideScratch scratch = new WideScratch();
    /** The last {@link #nearest} hit: {@code primitive} (shapes) or {@code triangle} (triangles) and {@code t}. */
    public final Hit hit = new Hit();

    private Walks(Bvh bvh, Leaves leaves) {
        this.bvh = bvh;
        this.leaves = leaves;
    }

    /** The shapes at the leaf slots of a tree over their boxes, tested as a scene's tree tests them ({@link ShapeLeaves}). */
    public static Walks ofShapes(Shape... shapes) {
        double[] boxes = new double[6 * shapes.length];
        for (int i = 0; i < shapes.length; i++) {
            shapes[i].bounds().copyTo(boxes, 6 * i);
        }
        Bvh bvh = Bvh.build(boxes, shapes.length);
        return new Walks(bvh, new ShapeLeaves(shapes.clone(), bvh.primitives()));
    }

    /**
     * Triangles (vertex index triples over {@code positions}, 3 doubles a vertex) at the leaf slots
     * of a tree over their boxes, tested as a mesh's tree tests them ({@link TriangleLeaves}).
     */
    public static Walks ofTriangles(double[] positions, int[] indices) {
        int count = indices.length / 3;
        double[] boxes = new double[6 * count];
        for (int t = 0; t < count; t++) {
            for (int k = 0; k < 3; k++) {
                double a = positions[3 * indices[3 * t] + k], b = positions[3 * indices[3 * t + 1] + k],
                        c = positions[3 * indices[3 * t + 2] + k];
                boxes[6 * t + k] = Math.min(a, Math.min(b, c));
                boxes[6 * t + 3 + k] = Math.max(a, Math.max(b, c));
            }
        }
        Bvh bvh = Bvh.build(boxes, count);
        int[] order = bvh.primitives(), sorted = new int[3 * count];
        for (int slot = 0; slot < count; slot++) {
            System.arraycopy(indices, 3 * order[slot], sorted, 3 * slot, 3);
        }
        return new Walks(bvh, new TriangleLeaves(positions, sorted));
    }

    /** The traversal walking the binary tree. */
    public Traversal binary() {
        return new Traversal(bvh.bounds(), bvh.nodes(), leaves, MemoryGate.UNLIMITED, false);
    }

    /** The traversal walking the wide tree collapsed from the binary one. */
    public Traversal wide() {
        return new Traversal(bvh.bounds(), bvh.nodes(), leaves, MemoryGate.UNLIMITED, true);
    }

    /** The box of all the primitives. */
    public Aabb bounds() {
        return bvh.rootBounds();
    }

    /**
     * The distance of the nearest hit with 0 &lt; t &lt; tMax through {@code walk}, NaN if none; its
     * primitive in {@link #hit}: a shape's declaration index in {@code primitive}, or a triangle's
     * slot in the tree in {@code triangle}.
     */
    public double nearest(Traversal walk, Ray ray, double tMax) {
        hit.primitive = ShapeLeaves.NONE;
        hit.triangle = -1;
        double cull = walk.nearest(ray, tMax, tMax, hit, stack, stackEntry, scratch);
        if (leaves instanceof ShapeLeaves) {
            return hit.primitive != ShapeLeaves.NONE ? hit.t : Double.NaN;
        }
        return hit.triangle >= 0 ? cull : Double.NaN;
    }

    /** Whether something lies on the ray with 0 &lt; t &lt; tMax, through {@code walk}. */
    public boolean any(Traversal walk, Ray ray, double tMax) {
        return walk.any(ray, tMax, scratch);
    }
}

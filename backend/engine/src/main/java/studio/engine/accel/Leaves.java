package studio.engine.accel;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;

/**
 * What a {@link Traversal} finds in its leaves: the primitives stored at leaf slots, tested a
 * leaf's run of slots at a time. Sealed with two kinds, the scene's shapes ({@link ShapeLeaves})
 * and a mesh's triangles ({@link TriangleLeaves}), so the traversal's call is bimorphic, which the
 * JIT inlines behind a type check: the kernel benchmark ({@code studio-bench.jar kernel}, spheres
 * and the mesh in one JVM) takes the CPU time it took with a copy of the walk per kind.
 */
public sealed interface Leaves permits ShapeLeaves, TriangleLeaves {

    /**
     * Tests slots {@code first .. end-1} for a nearer hit, recording the winner in {@code hit} as
     * the kind does; {@code tMax} is the query's limit, {@code cull} how far a hit could still win
     * so far. Returns the new cull distance (the same one if nothing won).
     */
    double nearest(int first, int end, Ray ray, double tMax, double cull, Hit hit);

    /** Whether any primitive at slots {@code first .. end-1} lies on the ray with 0 &lt; t &lt; tMax. */
    boolean any(int first, int end, Ray ray, double tMax);
}

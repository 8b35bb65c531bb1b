package studio.engine.geometry;

import studio.engine.accel.Bvh;
import studio.engine.accel.WideScratch;
import studio.engine.math.Vec3;

/**
 * The nearest intersection found so far: distance, point, outward shading normal (unit length; for
 * a smooth mesh the interpolated vertex normal, turned to the geometric normal's side), the
 * geometric normal of the surface itself (the same for every shape but a smooth mesh, whose is
 * its triangle's), and a conservative per-component bound on the point's rounding error. Shading
 * uses the shading normal; which side a ray is on, and which way a new ray's origin is moved off
 * the surface, use the geometric one (as pbrt does), so a bent vertex normal cannot put a new ray
 * on the wrong side of the triangle it leaves. Mutable and reused: one per
 * worker thread and recursion depth. It also carries the BVH traversal stacks, so a closest-hit
 * query allocates nothing.
 */
public final class Hit {

    public double t;
    public double px, py, pz;
    public double nx, ny, nz;
    /** The geometric normal: unit, outward (by the winding, for a triangle). */
    public double gx, gy, gz;
    /** Absolute error bound of each component of the hit point. */
    public double ex, ey, ez;
    /** Index of the primitive in its scene, in declaration order. */
    public int primitive;
    /**
     * On a mesh: the triangle hit (in the mesh's order) and the barycentric weights of its second and
     * third vertices, recorded for texture coordinates ({@link Shape#textureCoordinates}); other shapes
     * leave them as they are.
     */
    public int triangle;
    public double b1, b2;

    /** Traversal stack of the scene's BVH over its objects. */
    public final int[] sceneStack = new int[Bvh.STACK_SIZE];
    /** Where the ray enters each node on {@link #sceneStack}, so a node beyond the nearest hit so far is skipped. */
    public final double[] sceneStackEntry = new double[Bvh.STACK_SIZE];
    /** Traversal stack of a BVH inside one shape (a mesh's triangles), used while the scene's is in use. */
    public final int[] shapeStack = new int[Bvh.STACK_SIZE];
    /** Where the ray enters each node on {@link #shapeStack}. */
    public final double[] shapeStackEntry = new double[Bvh.STACK_SIZE];
    /** The scene's wide walk's working memory, where traversals walk wide trees (else null). */
    public final WideScratch sceneWide = WideScratch.ifUsed();
    /** A shape's wide walk's working memory, used while the scene's is in use (else null). */
    public final WideScratch shapeWide = WideScratch.ifUsed();

    /** A hit on a surface whose shading normal is its geometric normal. */
    void set(double t, double px, double py, double pz, double nx, double ny, double nz,
             double ex, double ey, double ez) {
        set(t, px, py, pz, nx, ny, nz, nx, ny, nz, ex, ey, ez);
    }

    /** A hit whose shading normal (nx, ny, nz) differs from the geometric one (gx, gy, gz). */
    void set(double t, double px, double py, double pz, double nx, double ny, double nz,
             double gx, double gy, double gz, double ex, double ey, double ez) {
        this.t = t;
        this.px = px; this.py = py; this.pz = pz;
        this.nx = nx; this.ny = ny; this.nz = nz;
        this.gx = gx; this.gy = gy; this.gz = gz;
        this.ex = ex; this.ey = ey; this.ez = ez;
    }

    public Vec3 point() {
        return new Vec3(px, py, pz);
    }

    public Vec3 normal() {
        return new Vec3(nx, ny, nz);
    }
}

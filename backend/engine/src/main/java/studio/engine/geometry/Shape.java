package studio.engine.geometry;

import studio.engine.accel.Aabb;

/**
 * A surface a ray can hit. Hits count only for 0 &lt; t &lt; tMax: secondary rays are offset by
 * the hit point's error bound ({@link Rays#spawn}), so no shape needs an epsilon of its own.
 */
public sealed interface Shape permits Sphere, Plane, Box, TriangleMesh {

    /**
     * Finds the nearest hit with 0 &lt; t &lt; tMax and fills {@code hit} (not its primitive index).
     * Leaves {@code hit} untouched and returns false when there is none.
     */
    boolean intersect(Ray ray, double tMax, Hit hit);

    /** Whether any hit with 0 &lt; t &lt; tMax exists (shadow rays). */
    boolean occluded(Ray ray, double tMax);

    /**
     * Whether the shape is convex: with any two of its points it holds the segment between them.
     * Then the rays from one point that it stops form a convex cone, so it stops every ray between
     * rays it stops (how an umbra is told from a penumbra: {@code LightSampler.hiddenBy}).
     */
    boolean convex();

    /**
     * A box holding every point the shape can report as a hit (conservatively rounded outwards),
     * or {@link Aabb#UNBOUNDED} for shapes without finite extent, which stay out of a BVH.
     */
    Aabb bounds();

    /**
     * Into {@code out}: the texture coordinates of {@code hit}, a hit this shape reported (its point
     * and normal; for a mesh, its triangle and barycentrics). Called once, for the hit being shaded
     * with a texture: spheres (longitude, latitude in 0..1, as three.js's SphereGeometry), planes
     * (world units along a tangent frame fixed by the normal), boxes (each face 0..1), meshes (their
     * vertices' UVs interpolated, or the barycentrics without UVs).
     */
    void textureCoordinates(Hit hit, TextureCoordinates out);
}

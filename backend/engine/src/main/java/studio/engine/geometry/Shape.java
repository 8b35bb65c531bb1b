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
     * A box holding every point the shape can report as a hit (conservatively rounded outwards),
     * or {@link Aabb#UNBOUNDED} for shapes without finite extent, which stay out of a BVH.
     */
    Aabb bounds();
}

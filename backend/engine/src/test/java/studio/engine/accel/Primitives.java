package studio.engine.accel;

import studio.engine.geometry.Ray;

/**
 * The primitive test a test or benchmark traversal ({@link BinaryWalk}, {@link WideWalk}) calls at
 * a leaf: the engine's own traversals inline theirs instead.
 */
public interface Primitives {

    /** The distance of primitive {@code p}'s nearest hit with 0 &lt; t &lt; tMax, or NaN if none. */
    double distance(int p, Ray ray, double tMax);

    /** The boxes of all primitives, six doubles each (minX, minY, minZ, maxX, maxY, maxZ). */
    double[] boxes();

    /** How many primitives there are. */
    int count();
}

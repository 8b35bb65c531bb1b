package studio.engine.accel;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Shape;
import studio.engine.geometry.Sphere;

/**
 * A scene's bounded shapes at the leaf slots of its tree, searched under the tie rule: of hits
 * within {@link #TIE} of each other the first-declared shape wins (robustness case NUM-12,
 * docs/robustness.md). The winner so far is {@code hit.primitive} (its declaration index, or
 * {@link #NONE}) at {@code hit.t}: a shape declared before it is asked for hits before the cull
 * distance {@code min(tMax, best*(1 + TIE))}, one declared after it for hits before
 * {@code best*(1 - TIE)}, and every hit then reported wins. For hits that form separate clusters
 * the lowest index of the nearest cluster wins in any visiting order, as in a linear loop.
 *
 * <p>A sphere's centre and radius sit in a flat array by slot and are tested through
 * {@link Sphere}'s static test, which the record itself calls, so the hit is the same to the bit:
 * this spares a call through {@link Shape} (megamorphic once spheres, boxes and meshes share a
 * tree) and two dependent loads (kernel benchmark, {@code studio-bench.jar kernel}).
 */
public final class ShapeLeaves implements Leaves {

    /** Hits whose distances differ by at most this fraction are a tie; the first-declared shape wins. */
    public static final double TIE = 1e-9;
    /** {@code hit.primitive} while no shape has won. */
    public static final int NONE = Integer.MAX_VALUE;

    private final Shape[] shapes;
    /** Per slot, the shape's declaration index. */
    private final int[] slotShapes;
    /** Per slot, a sphere's centre and radius; radius 0 marks a shape asked through {@link Shape}. */
    private final double[] slotSpheres;

    /** The shapes, by declaration index, of which {@code slotShapes[slot]} sits at each slot (kept, not copied). */
    public ShapeLeaves(Shape[] shapes, int[] slotShapes) {
        this.shapes = shapes;
        this.slotShapes = slotShapes;
        this.slotSpheres = new double[4 * slotShapes.length];
        for (int slot = 0; slot < slotShapes.length; slot++) {
            if (shapes[slotShapes[slot]] instanceof Sphere sphere) {
                slotSpheres[4 * slot] = sphere.center().x();
                slotSpheres[4 * slot + 1] = sphere.center().y();
                slotSpheres[4 * slot + 2] = sphere.center().z();
                slotSpheres[4 * slot + 3] = sphere.radius();
            }
        }
    }

    @Override
    public double nearest(int first, int end, Ray ray, double tMax, double cull, Hit hit) {
        double[] spheres = slotSpheres;
        for (int slot = first; slot < end; slot++) {
            int i = slotShapes[slot];
            double limit = i < hit.primitive ? cull : hit.t * (1 - TIE);
            int k = 4 * slot;
            boolean found = spheres[k + 3] != 0
                    ? Sphere.intersect(spheres[k], spheres[k + 1], spheres[k + 2], spheres[k + 3], ray, limit, hit)
                    : shapes[i].intersect(ray, limit, hit);
            if (found) {
                hit.primitive = i;
                cull = Math.min(tMax, hit.t * (1 + TIE));
            }
        }
        return cull;
    }

    @Override
    public boolean any(int first, int end, Ray ray, double tMax) {
        double[] spheres = slotSpheres;
        for (int slot = first; slot < end; slot++) {
            int k = 4 * slot;
            boolean found = spheres[k + 3] != 0
                    ? Sphere.occluded(spheres[k], spheres[k + 1], spheres[k + 2], spheres[k + 3], ray, tMax)
                    : shapes[slotShapes[slot]].occluded(ray, tMax);
            if (found) {
                ray.blocker = slotShapes[slot];
                return true;
            }
        }
        return false;
    }

    /** Whether shape i (by declaration index; false when there is none) lies on the ray with 0 &lt; t &lt; tMax. */
    public boolean blocks(int i, Ray ray, double tMax) {
        return i >= 0 && i < shapes.length && shapes[i].occluded(ray, tMax);
    }
}

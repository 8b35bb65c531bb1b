package studio.engine.accel;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Shape;

/**
 * A scene's planes, tested beside its tree under {@link ShapeLeaves}' tie rule. Their own kind,
 * not {@link ShapeLeaves}: held as {@link Plane}s, a plane's test is a direct call, and the loop
 * shares no type profile with the tree's leaves, whose boxes and meshes would make the call a
 * type switch (mirror-room, 6 planes among 8 objects: shadow rays spent about twice as long on
 * the planes through {@link ShapeLeaves}; JFR, one render thread).
 */
public final class PlaneLeaves {

    private final Plane[] planes;
    /** Per slot, the plane's declaration index. */
    private final int[] slotShapes;

    /** The shapes, by declaration index, of which {@code slotShapes[slot]} (each a {@link Plane}) sits at each slot. */
    public PlaneLeaves(Shape[] shapes, int[] slotShapes) {
        this.slotShapes = slotShapes.clone();
        this.planes = new Plane[slotShapes.length];
        for (int slot = 0; slot < slotShapes.length; slot++) {
            if (!(shapes[slotShapes[slot]] instanceof Plane plane)) {
                throw new IllegalArgumentException("not a plane: " + shapes[slotShapes[slot]]);
            }
            planes[slot] = plane;
        }
    }

    /** How many planes there are. */
    public int size() {
        return planes.length;
    }

    /** {@link Leaves#nearest} for slots {@code first .. end-1}, under the tie rule. */
    public double nearest(int first, int end, Ray ray, double tMax, double cull, Hit hit) {
        for (int slot = first; slot < end; slot++) {
            int i = slotShapes[slot];
            double limit = i < hit.primitive ? cull : hit.t * (1 - ShapeLeaves.TIE);
            if (planes[slot].intersect(ray, limit, hit)) {
                hit.primitive = i;
                cull = Math.min(tMax, hit.t * (1 + ShapeLeaves.TIE));
            }
        }
        return cull;
    }

    /** {@link Leaves#any} for slots {@code first .. end-1}; a plane found becomes {@link Ray#blocker}. */
    public boolean any(int first, int end, Ray ray, double tMax) {
        for (int slot = first; slot < end; slot++) {
            if (planes[slot].occluded(ray, tMax)) {
                ray.blocker = slotShapes[slot];
                return true;
            }
        }
        return false;
    }
}

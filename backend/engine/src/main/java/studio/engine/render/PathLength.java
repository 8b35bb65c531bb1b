package studio.engine.render;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.math.Vec3;

/**
 * How far light travels from the camera to the hit at {@code depth} along the current path (the
 * hits of shallower depths are its ancestors'): a texture's ray cone is as wide there as its spread
 * times this. Only a textured hit asks. (Curved mirrors and lenses widen a real cone further; the
 * cone here spreads as through flat ones.)
 */
final class PathLength {

    private PathLength() {
    }

    /** Along {@code hits[0 .. depth]}, the last reached by {@code ray}, from the camera at {@code eye}. */
    static double to(Hit[] hits, int depth, Ray ray, Vec3 eye) {
        Hit hit = hits[depth];
        if (depth == 0) {
            double x = hit.px - ray.ox, y = hit.py - ray.oy, z = hit.pz - ray.oz;
            return Math.sqrt(x * x + y * y + z * z);
        }
        Hit first = hits[0];
        double x = first.px - eye.x(), y = first.py - eye.y(), z = first.pz - eye.z();
        double length = Math.sqrt(x * x + y * y + z * z);
        for (int k = 1; k <= depth; k++) {
            Hit from = hits[k - 1], to = hits[k];
            x = to.px - from.px;
            y = to.py - from.py;
            z = to.pz - from.pz;
            length += Math.sqrt(x * x + y * y + z * z);
        }
        return length;
    }
}

package studio.engine.geometry;

/**
 * The one place secondary rays are made. The origin is moved off the surface along its geometric
 * normal by the hit point's error bound, to the side the new ray leaves from, then one ulp further
 * in each moved component (pbrt's OffsetRayOrigin). The geometric normal, not a smooth mesh's
 * interpolated one: the error bound is the point's distance from the triangle's plane, and only
 * its own normal says which side of that plane the new ray is on. New rays then accept any t &gt; 0: no fixed epsilon,
 * so it works at any scale and any distance from the origin.
 */
public final class Rays {

    private Rays() {
    }

    /** A ray leaving the hit point in direction (dx, dy, dz). */
    public static Ray spawn(Hit hit, double dx, double dy, double dz) {
        return spawn(hit, dx, dy, dz, new Ray());
    }

    /** A unit-direction ray from the hit point towards a target point (shadow rays). */
    public static Ray spawnTowards(Hit hit, double tx, double ty, double tz) {
        return spawnTowards(hit, tx, ty, tz, new Ray());
    }

    /** {@link #spawn(Hit, double, double, double)} into {@code out} (the hot loop reuses its rays); returns out. */
    public static Ray spawn(Hit hit, double dx, double dy, double dz, Ray out) {
        double offset = Math.abs(hit.gx) * hit.ex + Math.abs(hit.gy) * hit.ey + Math.abs(hit.gz) * hit.ez;
        boolean inward = hit.gx * dx + hit.gy * dy + hit.gz * dz < 0;
        if (inward) {
            offset = -offset;
        }
        double ox = step(hit.px, offset * hit.gx);
        double oy = step(hit.py, offset * hit.gy);
        double oz = step(hit.pz, offset * hit.gz);
        out.set(ox, oy, oz, dx, dy, dz);
        out.within = inward ? hit.primitive : -1; // against the outward normal: into the object
        return out;
    }

    /** {@link #spawnTowards(Hit, double, double, double)} into {@code out}; returns out. */
    public static Ray spawnTowards(Hit hit, double tx, double ty, double tz, Ray out) {
        double dx = tx - hit.px, dy = ty - hit.py, dz = tz - hit.pz;
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        return spawn(hit, dx / len, dy / len, dz / len, out);
    }

    private static double step(double p, double delta) {
        double moved = p + delta;
        if (delta > 0) {
            return Math.nextUp(moved);
        }
        if (delta < 0) {
            return Math.nextDown(moved);
        }
        return moved;
    }
}

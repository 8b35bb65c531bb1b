package studio.engine.light;

import java.util.List;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Sphere;

/**
 * The lights camera and specular rays can see: sphere lights and area lights (a point light has
 * no surface), each seen as its colour * intensity; a one-sided area light is seen from its front
 * only (from behind the ray passes it). Emitters are not objects of the scene: they cast no
 * shadows, so a shadow ray towards a light is never blocked by that light's own surface, nor by
 * another light's. One per worker thread; allocates nothing after construction.
 */
public final class Emitters {

    private final int count;
    /** The sphere and area lights: a sphere's radius is above 0, a rectangle's 0. */
    private final LightArrays lights;
    private final Hit scratch = new Hit();

    /** What the emitter found by the last {@link #nearest} shows, per channel. */
    public double r, g, b;

    public Emitters(List<? extends Light> lights) {
        List<? extends Light> soft = lights.stream().filter(Light::soft).toList();
        count = soft.size();
        this.lights = new LightArrays(soft);
    }

    /** Whether there is anything to see (no: only point lights). */
    public boolean any() {
        return count > 0;
    }

    /**
     * Whether the ray meets an emitter with 0 &lt; t &lt; tMax; if so what the nearest shows is in
     * r, g, b.
     */
    public boolean nearest(Ray ray, double tMax) {
        int found = -1;
        double best = tMax;
        for (int i = 0; i < count; i++) {
            double t = lights.radius[i] > 0 ? sphere(i, ray, best) : rectangle(i, ray, best);
            if (t < best) {
                best = t;
                found = i;
            }
        }
        if (found < 0) {
            return false;
        }
        r = lights.er[found];
        g = lights.eg[found];
        b = lights.eb[found];
        return true;
    }

    private double sphere(int i, Ray ray, double tMax) {
        return Sphere.intersect(lights.cx[i], lights.cy[i], lights.cz[i], lights.radius[i], ray, tMax, scratch)
                ? scratch.t : Double.POSITIVE_INFINITY;
    }

    /** The rectangle's hit distance, or infinity: the plane's t by division, then the point's offsets along the axes. */
    private double rectangle(int i, Ray ray, double tMax) {
        double dn = ray.dx * lights.nx[i] + ray.dy * lights.ny[i] + ray.dz * lights.nz[i];
        if (!(dn < 0 || lights.twoSided[i] && dn > 0)) {
            return Double.POSITIVE_INFINITY; // from behind a one-sided light, or edge-on
        }
        double ox = lights.cx[i] - ray.ox, oy = lights.cy[i] - ray.oy, oz = lights.cz[i] - ray.oz;
        double t = (ox * lights.nx[i] + oy * lights.ny[i] + oz * lights.nz[i]) / dn;
        if (!(t > 0 && t < tMax)) {
            return Double.POSITIVE_INFINITY;
        }
        double qx = ray.dx * t - ox, qy = ray.dy * t - oy, qz = ray.dz * t - oz;
        boolean inside = Math.abs(qx * lights.ux[i] + qy * lights.uy[i] + qz * lights.uz[i]) <= lights.halfWidth[i]
                && Math.abs(qx * lights.vx[i] + qy * lights.vy[i] + qz * lights.vz[i]) <= lights.halfHeight[i];
        return inside ? t : Double.POSITIVE_INFINITY;
    }
}

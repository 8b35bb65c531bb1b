package studio.engine.light;

import java.util.List;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Sphere;
import studio.engine.math.Vec3;

/**
 * The lights camera and specular rays can see: sphere lights and area lights (a point light has
 * no surface), each seen as its colour * intensity; a one-sided area light is seen from its front
 * only (from behind the ray passes it). Emitters are not objects of the scene: they cast no
 * shadows, so a shadow ray towards a light is never blocked by that light's own surface, nor by
 * another light's. One per worker thread; allocates nothing after construction.
 */
public final class Emitters {

    private final int count;
    /** Per emitter: sphere (radius > 0) or rectangle (radius 0), centre, normal, half axes, what it shows. */
    private final double[] radius, cx, cy, cz, nx, ny, nz, wx, wy, wz, hx, hy, hz, halfW, halfH, er, eg, eb;
    private final boolean[] twoSided;
    private final Hit scratch = new Hit();

    /** What the emitter found by the last {@link #nearest} shows, per channel. */
    public double r, g, b;

    public Emitters(List<? extends Light> lights) {
        List<? extends Light> soft = lights.stream().filter(Light::soft).toList();
        count = soft.size();
        radius = new double[count];
        cx = new double[count]; cy = new double[count]; cz = new double[count];
        nx = new double[count]; ny = new double[count]; nz = new double[count];
        wx = new double[count]; wy = new double[count]; wz = new double[count];
        hx = new double[count]; hy = new double[count]; hz = new double[count];
        halfW = new double[count]; halfH = new double[count];
        er = new double[count]; eg = new double[count]; eb = new double[count];
        twoSided = new boolean[count];
        for (int i = 0; i < count; i++) {
            Light light = soft.get(i);
            Vec3 p = light.position();
            cx[i] = p.x(); cy[i] = p.y(); cz[i] = p.z();
            er[i] = light.color().r() * light.intensity();
            eg[i] = light.color().g() * light.intensity();
            eb[i] = light.color().b() * light.intensity();
            if (light instanceof SphereLight sphere) {
                radius[i] = sphere.radius();
            } else if (light instanceof AreaLight area) {
                Vec3 n = area.normal(), w = area.widthAxis(), h = area.heightAxis();
                nx[i] = n.x(); ny[i] = n.y(); nz[i] = n.z();
                wx[i] = w.x(); wy[i] = w.y(); wz[i] = w.z();
                hx[i] = h.x(); hy[i] = h.y(); hz[i] = h.z();
                halfW[i] = area.width() / 2;
                halfH[i] = area.height() / 2;
                twoSided[i] = area.twoSided();
            }
        }
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
            double t = radius[i] > 0 ? sphere(i, ray, best) : rectangle(i, ray, best);
            if (t < best) {
                best = t;
                found = i;
            }
        }
        if (found < 0) {
            return false;
        }
        r = er[found];
        g = eg[found];
        b = eb[found];
        return true;
    }

    private double sphere(int i, Ray ray, double tMax) {
        return Sphere.intersect(cx[i], cy[i], cz[i], radius[i], ray, tMax, scratch) ? scratch.t
                : Double.POSITIVE_INFINITY;
    }

    /** The rectangle's hit distance, or infinity: the plane's t by division, then the point's offsets along the axes. */
    private double rectangle(int i, Ray ray, double tMax) {
        double dn = ray.dx * nx[i] + ray.dy * ny[i] + ray.dz * nz[i];
        if (!(dn < 0 || twoSided[i] && dn > 0)) {
            return Double.POSITIVE_INFINITY; // from behind a one-sided light, or edge-on
        }
        double ox = cx[i] - ray.ox, oy = cy[i] - ray.oy, oz = cz[i] - ray.oz;
        double t = (ox * nx[i] + oy * ny[i] + oz * nz[i]) / dn;
        if (!(t > 0 && t < tMax)) {
            return Double.POSITIVE_INFINITY;
        }
        double qx = ray.dx * t - ox, qy = ray.dy * t - oy, qz = ray.dz * t - oz;
        boolean inside = Math.abs(qx * wx[i] + qy * wy[i] + qz * wz[i]) <= halfW[i]
                && Math.abs(qx * hx[i] + qy * hy[i] + qz * hz[i]) <= halfH[i];
        return inside ? t : Double.POSITIVE_INFINITY;
    }
}

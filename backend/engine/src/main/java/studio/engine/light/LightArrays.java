package studio.engine.light;

import java.util.List;

import studio.engine.math.Vec3;

/**
 * A scene's lights as flat arrays, per light: what {@link LightSampler}, {@link WholeLight} and
 * {@link Emitters} read on every sample, without a call through {@link Light} or a Vec3 in the way.
 */
final class LightArrays {

    static final int POINT = 0, SPHERE = 1, AREA = 2;

    final int[] kind;
    final boolean[] falloff, twoSided;
    /** Centre, and colour * intensity. */
    final double[] cx, cy, cz, er, eg, eb;
    /** A sphere light's radius. */
    final double[] radius;
    /**
     * An area light's front normal, its half axes (vectors along width and height), its unit axes
     * (u along the width, v along the height), and half its width and height.
     */
    final double[] nx, ny, nz, wx, wy, wz, hx, hy, hz, ux, uy, uz, vx, vy, vz, halfWidth, halfHeight;

    LightArrays(List<? extends Light> lights) {
        int n = lights.size();
        kind = new int[n];
        falloff = new boolean[n];
        twoSided = new boolean[n];
        cx = new double[n]; cy = new double[n]; cz = new double[n];
        er = new double[n]; eg = new double[n]; eb = new double[n];
        radius = new double[n];
        nx = new double[n]; ny = new double[n]; nz = new double[n];
        wx = new double[n]; wy = new double[n]; wz = new double[n];
        hx = new double[n]; hy = new double[n]; hz = new double[n];
        ux = new double[n]; uy = new double[n]; uz = new double[n];
        vx = new double[n]; vy = new double[n]; vz = new double[n];
        halfWidth = new double[n]; halfHeight = new double[n];
        for (int i = 0; i < n; i++) {
            Light light = lights.get(i);
            Vec3 p = light.position();
            cx[i] = p.x(); cy[i] = p.y(); cz[i] = p.z();
            er[i] = light.color().r() * light.intensity();
            eg[i] = light.color().g() * light.intensity();
            eb[i] = light.color().b() * light.intensity();
            falloff[i] = light.falloff();
            if (light instanceof SphereLight sphere) {
                kind[i] = SPHERE;
                radius[i] = sphere.radius();
            } else if (light instanceof AreaLight area) {
                kind[i] = AREA;
                twoSided[i] = area.twoSided();
                Vec3 normal = area.normal(), u = area.widthAxis(), v = area.heightAxis();
                Vec3 w = u.times(area.width() / 2), h = v.times(area.height() / 2);
                nx[i] = normal.x(); ny[i] = normal.y(); nz[i] = normal.z();
                wx[i] = w.x(); wy[i] = w.y(); wz[i] = w.z();
                hx[i] = h.x(); hy[i] = h.y(); hz[i] = h.z();
                ux[i] = u.x(); uy[i] = u.y(); uz[i] = u.z();
                vx[i] = v.x(); vy[i] = v.y(); vz[i] = v.z();
                halfWidth[i] = area.width() / 2;
                halfHeight[i] = area.height() / 2;
            } else {
                kind[i] = POINT;
            }
        }
    }
}

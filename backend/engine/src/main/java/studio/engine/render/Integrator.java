package studio.engine.render;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Rays;
import studio.engine.light.PointLight;
import studio.engine.material.Fresnel;
import studio.engine.material.Material;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.scene.Scene;

/**
 * Whitted-style ray tracing in linear light: direct light from point lights with hard shadows,
 * an ambient term, mirror reflection and Fresnel-weighted refraction, recursing up to maxDepth and
 * only where a material asks for it and the path's weight can still change the pixel.
 *
 * <p>Shadows through glass: a shadow ray passes through glass surfaces, losing the Fresnel
 * reflectance at each and taking the glass's tint on the way in, so glass casts a lighter, tinted
 * shadow. The light is assumed to go straight through (no caustic focusing): a ray tracer that
 * traces from the eye cannot find the bent path to a point light, and a black shadow under clear
 * glass looks more wrong than a light one.
 *
 * <p>One instance per worker thread: it owns its hit records and counts its rays.
 */
final class Integrator {

    /** At most this many glass surfaces are crossed by one shadow ray before it counts as blocked. */
    private static final int MAX_SHADOW_CROSSINGS = 32;
    /** A shadow ray is blocked only by hits closer than this fraction of the light's distance. */
    private static final double SHADOW_END = 1 - 1e-9;

    private final Scene scene;
    private final int maxDepth;
    private final double minPathWeight;
    private final Hit[] hits;
    private final Hit shadowHit = new Hit();
    long rays;

    Integrator(Scene scene, int maxDepth, double minPathWeight) {
        this.scene = scene;
        this.maxDepth = maxDepth;
        this.minPathWeight = minPathWeight;
        this.hits = new Hit[maxDepth + 1];
        for (int i = 0; i < hits.length; i++) {
            hits[i] = new Hit();
        }
    }

    /** Radiance arriving along the ray; {@code weight} is the path's throughput so far (1 for a camera ray). */
    Rgb trace(Ray ray, int depth, double weight) {
        rays++;
        Hit hit = hits[depth];
        if (!scene.intersect(ray, Double.POSITIVE_INFINITY, hit)) {
            return scene.background();
        }
        Material m = scene.material(hit.primitive);
        if (m.kind() == MaterialKind.FLAT) {
            return m.color();
        }
        double dLen = Math.sqrt(ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz);
        double dx = ray.dx / dLen, dy = ray.dy / dLen, dz = ray.dz / dLen;
        double cosOut = hit.nx * dx + hit.ny * dy + hit.nz * dz;
        boolean front = cosOut < 0;
        // The shading normal faces the viewer.
        double sx = front ? hit.nx : -hit.nx, sy = front ? hit.ny : -hit.ny, sz = front ? hit.nz : -hit.nz;

        Rgb result = direct(m, hit, sx, sy, sz, -dx, -dy, -dz, front);
        if (depth >= maxDepth) {
            return result;
        }
        double cosView = -(sx * dx + sy * dy + sz * dz);
        if (m.kind() == MaterialKind.GLASS) {
            return result.plus(glass(m, hit, dx, dy, dz, front, depth, weight));
        }
        if (m.reflectivity() > 0) {
            Rgb tint = m.color().times(m.reflectivity());
            double w = weight * tint.max();
            if (w > minPathWeight) {
                double rx = dx + 2 * cosView * sx, ry = dy + 2 * cosView * sy, rz = dz + 2 * cosView * sz;
                result = result.plus(tint.times(trace(Rays.spawn(hit, rx, ry, rz), depth + 1, w)));
            }
        }
        return result;
    }

    /** Ambient, diffuse and highlight from every light the point sees. */
    private Rgb direct(Material m, Hit hit, double nx, double ny, double nz, double vx, double vy, double vz,
                       boolean front) {
        double kd = m.diffuse(), ks = m.specular();
        if (m.kind() == MaterialKind.GLASS && !front) {
            ks = 0;
        }
        if (kd == 0 && ks == 0) {
            return Rgb.BLACK;
        }
        Rgb albedo = m.color().times(kd);
        double r = albedo.r() * scene.ambient(), g = albedo.g() * scene.ambient(), b = albedo.b() * scene.ambient();
        Rgb specTint = m.specularTint().times(ks);
        for (PointLight light : scene.lights()) {
            double lx = light.position().x() - hit.px, ly = light.position().y() - hit.py,
                    lz = light.position().z() - hit.pz;
            double dist = Math.sqrt(lx * lx + ly * ly + lz * lz);
            double pLen = Math.abs(hit.px) + Math.abs(hit.py) + Math.abs(hit.pz);
            if (!(dist > 1e-12 * (1 + pLen))) {
                continue; // a light on the point itself lights nothing
            }
            lx /= dist; ly /= dist; lz /= dist;
            double cos = nx * lx + ny * ly + nz * lz;
            if (cos <= 0) {
                continue;
            }
            Rgb e = light.power();
            if (light.falloff()) {
                e = e.times(1 / (dist * dist));
            }
            Rgb through = shadowTransmittance(hit, light);
            if (through.isBlack()) {
                continue;
            }
            e = e.times(through);
            if (kd > 0) {
                r += albedo.r() * e.r() * cos;
                g += albedo.g() * e.g() * cos;
                b += albedo.b() * e.b() * cos;
            }
            if (ks > 0) {
                double hx = lx + vx, hy = ly + vy, hz = lz + vz;
                double hLen = Math.sqrt(hx * hx + hy * hy + hz * hz);
                double cosH = hLen > 0 ? (nx * hx + ny * hy + nz * hz) / hLen : 0;
                if (cosH > 0) {
                    double s = Math.pow(cosH, m.shininess());
                    r += specTint.r() * e.r() * s;
                    g += specTint.g() * e.g() * s;
                    b += specTint.b() * e.b() * s;
                }
            }
        }
        return new Rgb(r, g, b);
    }

    /** What fraction of a light reaches the hit point: 0 behind anything opaque, less through glass. */
    private Rgb shadowTransmittance(Hit from, PointLight light) {
        double tx = light.position().x(), ty = light.position().y(), tz = light.position().z();
        Ray ray = Rays.spawnTowards(from, tx, ty, tz);
        double dist = distance(ray, tx, ty, tz);
        rays++;
        if (!scene.hasGlass()) {
            return scene.occluded(ray, dist * SHADOW_END) ? Rgb.BLACK : Rgb.WHITE;
        }
        double r = 1, g = 1, b = 1;
        for (int crossing = 0; crossing < MAX_SHADOW_CROSSINGS; crossing++) {
            if (!scene.intersect(ray, dist * SHADOW_END, shadowHit)) {
                return new Rgb(r, g, b);
            }
            Material m = scene.material(shadowHit.primitive);
            if (m.kind() != MaterialKind.GLASS) {
                return Rgb.BLACK;
            }
            double cos = shadowHit.nx * ray.dx + shadowHit.ny * ray.dy + shadowHit.nz * ray.dz;
            boolean entering = cos < 0;
            double transmitted = 1 - (entering ? Fresnel.reflectance(-cos, 1, m.ior())
                    : Fresnel.reflectance(cos, m.ior(), 1));
            r *= transmitted;
            g *= transmitted;
            b *= transmitted;
            if (entering) {
                r *= m.color().r();
                g *= m.color().g();
                b *= m.color().b();
            }
            if (Math.max(r, Math.max(g, b)) <= minPathWeight) {
                return Rgb.BLACK;
            }
            ray = Rays.spawnTowards(shadowHit, tx, ty, tz);
            dist = distance(ray, tx, ty, tz);
            rays++;
        }
        return Rgb.BLACK;
    }

    private static double distance(Ray ray, double tx, double ty, double tz) {
        double x = tx - ray.ox, y = ty - ray.oy, z = tz - ray.oz;
        return Math.sqrt(x * x + y * y + z * z);
    }

    /** Fresnel-weighted reflection plus refraction (or total internal reflection). */
    private Rgb glass(Material m, Hit hit, double dx, double dy, double dz, boolean front, int depth, double weight) {
        // n points against the incoming ray, into the medium the ray comes from.
        double nx = front ? hit.nx : -hit.nx, ny = front ? hit.ny : -hit.ny, nz = front ? hit.nz : -hit.nz;
        double etaI = front ? 1 : m.ior(), etaT = front ? m.ior() : 1;
        double cosI = Math.min(1, Math.max(0, -(nx * dx + ny * dy + nz * dz)));
        double eta = etaI / etaT;
        double k = 1 - eta * eta * (1 - cosI * cosI);
        double reflectance = k <= 0 ? 1 : Fresnel.reflectance(cosI, etaI, etaT);

        Rgb result = Rgb.BLACK;
        double wr = weight * reflectance;
        if (wr > minPathWeight) {
            double rx = dx + 2 * cosI * nx, ry = dy + 2 * cosI * ny, rz = dz + 2 * cosI * nz;
            result = trace(Rays.spawn(hit, rx, ry, rz), depth + 1, wr).times(reflectance);
        }
        if (k > 0) {
            Rgb tint = front ? m.color() : Rgb.WHITE;
            double transmittance = 1 - reflectance;
            double wt = weight * transmittance * tint.max();
            if (wt > minPathWeight) {
                double c = eta * cosI - Math.sqrt(k);
                double tx = eta * dx + c * nx, ty = eta * dy + c * ny, tz = eta * dz + c * nz;
                Rgb through = trace(Rays.spawn(hit, tx, ty, tz), depth + 1, wt);
                result = result.plus(through.times(tint).times(transmittance));
            }
        }
        return result;
    }
}

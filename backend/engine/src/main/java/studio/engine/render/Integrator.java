package studio.engine.render;

import java.util.Arrays;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Rays;
import studio.engine.light.Emitters;
import studio.engine.light.LightSampler;
import studio.engine.material.Fresnel;
import studio.engine.material.Material;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.scene.Scene;
import studio.engine.texture.Texture;
import studio.engine.texture.TextureLookup;

/**
 * Whitted-style ray tracing in linear light: direct light by one shadow ray a light ({@link LightSampler}),
 * lights with a surface seen by camera and specular rays ({@link Emitters}),
 * an ambient term, mirror reflection and Fresnel-weighted refraction, recursing up to maxDepth and
 * only where a material asks for it and the path's weight can still change the pixel. At glass,
 * a weak branch of the split plays a {@link BranchRoulette}.
 *
 * <p>Shadows through glass: a shadow ray passes through glass surfaces, losing the Fresnel
 * reflectance at each and taking the glass's tint on the way in, so glass casts a lighter, tinted
 * shadow. The light is assumed to go straight through (no caustic focusing): a ray tracer that
 * traces from the eye cannot find the bent path to a point light, and a black shadow under clear
 * glass looks more wrong than a light one.
 *
 * <p>One instance per worker thread: it owns its hit records, rays and radiance slots (one of each
 * per recursion depth, so tracing allocates nothing) and counts its rays.
 */
final class Integrator {

    /** At most this many glass surfaces are crossed by one shadow ray before it counts as blocked. */
    private static final int MAX_SHADOW_CROSSINGS = 32;
    /** A shadow ray is blocked only by hits closer than this fraction of the light's distance. */
    private static final double SHADOW_END = 1 - 1e-9;
    /**
     * A light whose unshadowed share of a sample (the path's weight times what the light would add,
     * in units of white) is below this adds nothing an image can show, and its shadow ray is not
     * traced: the smallest step of 8-bit sRGB is 3e-4. Glass's highlight (shininess 250) is below it
     * at most points: in held-out glass, 1.23 million of the 1.32 million shadow rays from glass (of
     * 9.9 million in all).
     */
    static final double NEGLIGIBLE_LIGHT = 1e-6;

    static {
        // The calls a render may first reach late, its first reflection and its first shadow ray
        // through glass, are made once here so that they are resolved before the JIT compiles the
        // methods that hold them (every site of one method shares the class's resolved entry). C2
        // compiles a call it has not seen resolved as a trap: cold renders (with the start-up cache)
        // deoptimized trace at a still life's first mirror and shadowTransmittance at glass's
        // first crossing, every time, each then run in slower code and compiled again.
        Rays.spawn(new Hit(), 0, 0, 1, new Ray());
        Fresnel.reflectance(1, 1, 1.5);
    }

    private final Scene scene;
    private final int maxDepth;
    private final double minPathWeight;
    /** Decides which weak branches at glass are traced; the caller starts each sample on it. */
    final BranchRoulette roulette;
    /** Per recursion depth: the hit, the ray a surface at that depth spawns, and the radiance found. */
    private final Hit[] hits;
    private final Ray[] childRays;
    private final double[] radiance;
    private final Hit shadowHit = new Hit();
    private final Ray shadowRay = new Ray();
    /**
     * Per light, the opaque object that blocked this thread's last shadow ray to it (-1: none),
     * tested first: neighbouring points are mostly shadowed by the same object, which then spares
     * the search through the scene, and in a scene with glass the walk through every glass surface
     * on the way (a shadow cache, as POV-Ray keeps one per light).
     */
    private final int[] lastOccluder;
    /** Where this sample's shadow rays go on each light, and what camera and specular rays see of them. */
    private final LightSampler lightSampler;
    private final Emitters emitters;
    /** The current sample's 2D point in [0, 1)^2 for its light samples; set by the caller. */
    double lightU = 0.5, lightV = 0.5;
    /** The direct light found by {@link #direct}, and the transmittance by {@link #shadowTransmittance}. */
    private double directR, directG, directB, throughR, throughG, throughB;
    long rays;
    /** Where the rays of the pixel being traced are recorded (null: nowhere), and that pixel's index. */
    PixelPaths paths;
    int pathPixel;

    /**
     * The ray cone's spread (radians) for texture filtering: a pixel's angle over the square root of
     * its samples, times {@link SampleTracer#FOOTPRINT_SHARE} (0: textures are point-sampled). Set by
     * the caller.
     */
    double coneSpread;
    /** Looks textures up at textured hits only: untextured shading never touches it. */
    private final TextureLookup textures = new TextureLookup();

    /** What the current pixel's camera rays and their shadow rays can meet; set by the caller. */
    final PixelCandidates candidates;

    /** Tracing every branch at glass (no roulette): each ray's radiance is a deterministic function of it. */
    Integrator(Scene scene, int maxDepth, double minPathWeight) {
        this(scene, maxDepth, minPathWeight, BranchRoulette.none());
    }

    Integrator(Scene scene, int maxDepth, double minPathWeight, BranchRoulette roulette) {
        this.scene = scene;
        this.maxDepth = maxDepth;
        this.minPathWeight = minPathWeight;
        this.roulette = roulette;
        this.hits = new Hit[maxDepth + 1];
        this.childRays = new Ray[maxDepth + 1];
        for (int i = 0; i < hits.length; i++) {
            hits[i] = new Hit();
            childRays[i] = new Ray();
        }
        this.radiance = new double[3 * (maxDepth + 1)];
        this.lastOccluder = new int[scene.lights().size()];
        Arrays.fill(lastOccluder, -1);
        this.candidates = new PixelCandidates(scene);
        this.lightSampler = new LightSampler(scene.lights());
        this.emitters = new Emitters(scene.lights());
    }

    /** The red, green and blue radiance found by the last {@link #trace} at depth 0. */
    double r() {
        return radiance[0];
    }

    double g() {
        return radiance[1];
    }

    double b() {
        return radiance[2];
    }

    /**
     * Radiance arriving along the ray, into radiance[3 depth ..]; {@code weight} is the path's
     * throughput so far (1 for a camera ray). Allocates nothing: rays and hits are reused per depth.
     */
    void trace(Ray ray, int depth, double weight) {
        trace(ray, depth, weight, -1);
    }

    /**
     * {@link #trace(Ray, int, double)} for a ray that most likely ends on object {@code likely}
     * (-1: none): one refracted into a glass object, or reflected inside it, leaves it next, and
     * testing it first lets the search skip everything beyond.
     */
    private void trace(Ray ray, int depth, double weight, int likely) {
        rays++;
        int out = 3 * depth;
        Hit hit = hits[depth];
        boolean found = depth == 0 && candidates.cameraCount >= 0
                ? scene.intersectNearFirst(candidates.camera, candidates.cameraNear, candidates.cameraCount, ray,
                        Double.POSITIVE_INFINITY, hit)
                : scene.intersect(ray, Double.POSITIVE_INFINITY, hit, likely);
        if (emitters.any() && emitters.nearest(ray, found ? hit.t : Double.POSITIVE_INFINITY)) {
            radiance[out] = emitters.r; radiance[out + 1] = emitters.g; radiance[out + 2] = emitters.b;
            return;
        }
        if (!found) {
            if (paths != null) {
                paths.record(pathPixel, depth, ray.dx, ray.dy, ray.dz, true);
            }
            set(out, scene.background());
            return;
        }
        if (paths != null) {
            paths.record(pathPixel, depth, hit.px, hit.py, hit.pz, false);
        }
        Material m = scene.material(hit.primitive);
        Rgb color = m.color();
        double cr = color.r(), cg = color.g(), cb = color.b(), cMax;
        Texture texture = m.texture();
        if (texture == null) {
            cMax = color.max();
        } else {
            double dLen = Math.sqrt(ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz);
            textures.lookup(texture, scene.shape(hit.primitive), hit, ray.dx / dLen, ray.dy / dLen, ray.dz / dLen,
                    coneSpread * pathLength(ray, depth));
            cr *= textures.r;
            cg *= textures.g;
            cb *= textures.b;
            cMax = Math.max(cr, Math.max(cg, cb));
        }
        if (m.kind() == MaterialKind.FLAT) {
            radiance[out] = cr;
            radiance[out + 1] = cg;
            radiance[out + 2] = cb;
            return;
        }
        double dLen = Math.sqrt(ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz);
        double dx = ray.dx / dLen, dy = ray.dy / dLen, dz = ray.dz / dLen;
        // Which side of the surface the ray comes from is the geometric normal's call; the shading
        // normal is turned to that side.
        boolean front = hit.gx * dx + hit.gy * dy + hit.gz * dz < 0;
        double sx = front ? hit.nx : -hit.nx, sy = front ? hit.ny : -hit.ny, sz = front ? hit.nz : -hit.nz;

        direct(m, cr, cg, cb, hit, sx, sy, sz, -dx, -dy, -dz, front, depth == 0, weight);
        double r = directR, g = directG, b = directB;
        if (depth < maxDepth) {
            double cosView = -(sx * dx + sy * dy + sz * dz);
            if (m.kind() == MaterialKind.GLASS) {
                glass(m, cr, cg, cb, cMax, hit, dx, dy, dz, front, depth, weight);
                int child = out + 3;
                r += radiance[child];
                g += radiance[child + 1];
                b += radiance[child + 2];
            } else if (m.reflectivity() > 0) {
                double k = m.reflectivity();
                double w = weight * cMax * k;
                if (w > minPathWeight) {
                    double rx = dx + 2 * cosView * sx, ry = dy + 2 * cosView * sy, rz = dz + 2 * cosView * sz;
                    trace(Rays.spawn(hit, rx, ry, rz, childRays[depth]), depth + 1, w);
                    int child = out + 3;
                    r += cr * k * radiance[child];
                    g += cg * k * radiance[child + 1];
                    b += cb * k * radiance[child + 2];
                }
            }
        }
        radiance[out] = r;
        radiance[out + 1] = g;
        radiance[out + 2] = b;
    }

    /**
     * How far light travels from the camera to the hit at {@code depth} along the current path (the
     * hits of shallower depths are its ancestors'): the ray cone's width there is the spread times
     * this. Only a textured hit asks. (Curved mirrors and lenses widen a real cone further; the
     * cone here spreads as through flat ones.)
     */
    private double pathLength(Ray ray, int depth) {
        Hit hit = hits[depth];
        if (depth == 0) {
            return distance(ray, hit.px, hit.py, hit.pz);
        }
        Vec3 eye = scene.camera().position();
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

    private void set(int out, Rgb c) {
        radiance[out] = c.r();
        radiance[out + 1] = c.g();
        radiance[out + 2] = c.b();
    }

    /**
     * Ambient, diffuse and highlight from every light the point sees, into directR/G/B; a light
     * that could add only a {@link #NEGLIGIBLE_LIGHT} share to a path of this weight is not looked for.
     */
    private void direct(Material m, double cr, double cg, double cb, Hit hit, double nx, double ny, double nz,
                        double vx, double vy, double vz, boolean front, boolean cameraHit, double weight) {
        double kd = m.diffuse(), ks = m.specular();
        if (m.kind() == MaterialKind.GLASS && !front) {
            ks = 0;
        }
        if (kd == 0 && ks == 0) {
            directR = directG = directB = 0;
            return;
        }
        // a metal's highlight takes its (textured) colour; the others' are white
        boolean metal = m.kind() == MaterialKind.METAL;
        double ar = cr * kd, ag = cg * kd, ab = cb * kd;
        double sr = (metal ? cr : 1) * ks, sg = (metal ? cg : 1) * ks, sb = (metal ? cb : 1) * ks;
        double r = ar * scene.ambient(), g = ag * scene.ambient(), b = ab * scene.ambient();
        double aMax = Math.max(ar, Math.max(ag, ab)), sMax = Math.max(sr, Math.max(sg, sb));
        LightSampler light = lightSampler;
        for (int i = 0; i < lastOccluder.length; i++) {
            if (!light.sample(i, hit.px, hit.py, hit.pz, lightU, lightV)) {
                continue;
            }
            double lx = light.lx, ly = light.ly, lz = light.lz;
            double cos = nx * lx + ny * ly + nz * lz;
            if (cos <= 0) {
                continue;
            }
            double er = light.r, eg = light.g, eb = light.b;
            // the light's unshadowed share: the diffuse part mostly settles it; the highlight (a pow)
            // is worked out first only where it decides, else only for a point the light reaches
            double share = weight * Math.max(er, Math.max(eg, eb));
            double diffuseShare = kd > 0 ? share * aMax * cos : 0;
            boolean highlightDecides = diffuseShare < NEGLIGIBLE_LIGHT;
            double highlight = highlightDecides && ks > 0
                    ? highlight(nx, ny, nz, lx, ly, lz, vx, vy, vz, m.shininess()) : 0;
            if (highlightDecides && diffuseShare + share * sMax * highlight < NEGLIGIBLE_LIGHT) {
                continue;
            }
            if (!shadowTransmittance(hit, light.tx, light.ty, light.tz, i, cameraHit && light.isPoint(i))) {
                continue;
            }
            if (!highlightDecides && ks > 0) {
                highlight = highlight(nx, ny, nz, lx, ly, lz, vx, vy, vz, m.shininess());
            }
            er *= throughR;
            eg *= throughG;
            eb *= throughB;
            if (kd > 0) {
                r += ar * er * cos;
                g += ag * eg * cos;
                b += ab * eb * cos;
            }
            if (highlight > 0) {
                r += sr * er * highlight;
                g += sg * eg * highlight;
                b += sb * eb * highlight;
            }
        }
        directR = r;
        directG = g;
        directB = b;
    }

    /** Blinn-Phong's highlight for the light's direction l and the view's v (both unit): 0 when it faces away. */
    private static double highlight(double nx, double ny, double nz, double lx, double ly, double lz,
                                    double vx, double vy, double vz, double shininess) {
        double hx = lx + vx, hy = ly + vy, hz = lz + vz;
        double hLen = Math.sqrt(hx * hx + hy * hy + hz * hz);
        double cosH = hLen > 0 ? (nx * hx + ny * hy + nz * hz) / hLen : 0;
        return cosH > 0 ? Math.pow(cosH, shininess) : 0;
    }

    /**
     * What fraction of a light reaches the hit point, into throughR/G/B: 0 behind anything opaque,
     * less through glass. Returns false when nothing arrives. An any-hit search decides first:
     * nothing on the way, or an opaque object, settles it; only when it meets glass does the walk
     * from surface to surface follow, which finds the same opaque object or multiplies the glass's
     * transmittance (the same pixels to the bit, and glass-mirrors 4% faster at 16 samples). Only
     * rays to point lights use the pixel's list ({@code listed}) and the light's buffer.
     */
    private boolean shadowTransmittance(Hit from, double tx, double ty, double tz, int lightIndex, boolean listed) {
        Ray ray = Rays.spawnTowards(from, tx, ty, tz, shadowRay);
        double dist = distance(ray, tx, ty, tz);
        rays++;
        throughR = throughG = throughB = 1;
        int last = lastOccluder[lightIndex];
        if (last >= 0 && scene.occludes(last, ray, dist * SHADOW_END)) {
            return false; // an opaque object on the way: nothing arrives, whatever glass is crossed too
        }
        int among = listed ? candidates.shadowCount(lightIndex) : -1;
        int occluder = among >= 0 ? scene.occluderAmong(candidates.shadow(lightIndex), among, ray, dist * SHADOW_END)
                : lightSampler.isPoint(lightIndex) ? scene.occluderTowards(lightIndex, ray, dist * SHADOW_END)
                : scene.occluder(ray, dist * SHADOW_END);
        if (occluder < 0 || scene.material(occluder).kind() != MaterialKind.GLASS) {
            // nothing on the way, or something opaque: no walk through glass needed
            lastOccluder[lightIndex] = occluder;
            return occluder < 0;
        }
        double r = 1, g = 1, b = 1;
        int inside = -1; // the glass object the ray has entered, which it most likely leaves next
        for (int crossing = 0; crossing < MAX_SHADOW_CROSSINGS; crossing++) {
            if (!scene.intersect(ray, dist * SHADOW_END, shadowHit, inside)) {
                throughR = r;
                throughG = g;
                throughB = b;
                return true;
            }
            Material m = scene.material(shadowHit.primitive);
            if (m.kind() != MaterialKind.GLASS) {
                lastOccluder[lightIndex] = shadowHit.primitive;
                return false;
            }
            double cos = shadowHit.nx * ray.dx + shadowHit.ny * ray.dy + shadowHit.nz * ray.dz;
            boolean entering = shadowHit.gx * ray.dx + shadowHit.gy * ray.dy + shadowHit.gz * ray.dz < 0;
            inside = entering ? shadowHit.primitive : -1;
            // |cos|: a smooth mesh's shading normal may lean past the side its triangle is crossed from
            double transmitted = 1 - (entering ? Fresnel.reflectance(Math.abs(cos), 1, m.ior())
                    : Fresnel.reflectance(Math.abs(cos), m.ior(), 1));
            r *= transmitted;
            g *= transmitted;
            b *= transmitted;
            if (entering) {
                r *= m.color().r();
                g *= m.color().g();
                b *= m.color().b();
            }
            if (Math.max(r, Math.max(g, b)) <= minPathWeight) {
                return false;
            }
            ray = Rays.spawnTowards(shadowHit, tx, ty, tz, shadowRay);
            dist = distance(ray, tx, ty, tz);
            rays++;
        }
        return false;
    }

    /**
     * How many times a branch of path weight {@code w} at glass counts: 0 (not traced) when it is
     * too weak to change the pixel, else as its roulette decides (1 for a branch that is not weak).
     */
    private double branchCount(double w) {
        return w > minPathWeight ? roulette.factor(w) : 0;
    }

    private static double distance(Ray ray, double tx, double ty, double tz) {
        double x = tx - ray.ox, y = ty - ray.oy, z = tz - ray.oz;
        return Math.sqrt(x * x + y * y + z * z);
    }

    /**
     * Fresnel-weighted reflection plus refraction (or total internal reflection), into
     * radiance[3 (depth + 1) ..]; a branch too weak to change the pixel is left out, and a weak one
     * plays the roulette.
     */
    private void glass(Material m, double cr, double cg, double cb, double cMax, Hit hit, double dx, double dy,
                       double dz, boolean front, int depth, double weight) {
        // n points against the incoming ray, into the medium the ray comes from.
        double nx = front ? hit.nx : -hit.nx, ny = front ? hit.ny : -hit.ny, nz = front ? hit.nz : -hit.nz;
        double etaI = front ? 1 : m.ior(), etaT = front ? m.ior() : 1;
        double cosI = Math.min(1, Math.max(0, -(nx * dx + ny * dy + nz * dz)));
        double eta = etaI / etaT;
        double k = 1 - eta * eta * (1 - cosI * cosI);
        double reflectance = k <= 0 ? 1 : Fresnel.reflectance(cosI, etaI, etaT);

        int child = 3 * (depth + 1);
        double r = 0, g = 0, b = 0;
        double wr = weight * reflectance;
        double countR = branchCount(wr);
        if (countR > 0) {
            double rx = dx + 2 * cosI * nx, ry = dy + 2 * cosI * ny, rz = dz + 2 * cosI * nz;
            // reflected inside the object (from its back face), the ray meets it again
            trace(Rays.spawn(hit, rx, ry, rz, childRays[depth]), depth + 1, wr * countR, front ? -1 : hit.primitive);
            double kr = reflectance * countR;
            r = radiance[child] * kr;
            g = radiance[child + 1] * kr;
            b = radiance[child + 2] * kr;
        }
        if (k > 0) {
            double tr = front ? cr : 1, tg = front ? cg : 1, tb = front ? cb : 1;
            double wt = weight * (1 - reflectance) * (front ? cMax : 1);
            double countT = branchCount(wt);
            if (countT > 0) {
                double c = eta * cosI - Math.sqrt(k);
                double tx = eta * dx + c * nx, ty = eta * dy + c * ny, tz = eta * dz + c * nz;
                // refracted into the object, the ray leaves it next
                trace(Rays.spawn(hit, tx, ty, tz, childRays[depth]), depth + 1, wt * countT, front ? hit.primitive : -1);
                double kt = (1 - reflectance) * countT;
                r += radiance[child] * tr * kt;
                g += radiance[child + 1] * tg * kt;
                b += radiance[child + 2] * tb * kt;
            }
        }
        radiance[child] = r;
        radiance[child + 1] = g;
        radiance[child + 2] = b;
    }
}

package studio.engine.render;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Rays;
import studio.engine.light.Emitters;
import studio.engine.light.LightSampler;
import studio.engine.material.Fresnel;
import studio.engine.material.Material;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.scene.Scene;
import studio.engine.texture.Texture;
import studio.engine.texture.TextureLookup;

/**
 * Whitted-style ray tracing in linear light: direct light by one shadow ray a light ({@link LightSampler};
 * under adaptive sampling none to a light the point sees whole, {@link WholeLitPoints}),
 * lights with a surface seen by camera and specular rays ({@link Emitters}),
 * an ambient term, mirror reflection and Fresnel-weighted refraction, recursing up to maxDepth and
 * only where a material asks for it and the path's weight can still change the pixel. At glass,
 * a weak branch of the split plays a {@link BranchRoulette}.
 *
 * <p>Shadow rays, through glass too, are {@link ShadowRays}'.
 *
 * <p>One instance per worker thread: it owns its hit records, rays and radiance slots (one of each
 * per recursion depth, so tracing allocates nothing) and counts its rays.
 */
final class Integrator {

    /**
     * A light whose unshadowed share of a sample (the path's weight times what the light would add,
     * in units of white) is below this adds nothing an image can show, and its shadow ray is not
     * traced: the smallest step of 8-bit sRGB is 3e-4. Glass's highlight (shininess 250) is below it
     * at most points, so most shadow rays from glass are not traced (docs/speed.md).
     */
    static final double NEGLIGIBLE_LIGHT = 1e-6;

    static {
        // The calls a render may first reach late, its first reflection and its first shadow ray
        // through glass, are made once here so that they are resolved before the JIT compiles the
        // methods that hold them (every site of one method shares the class's resolved entry). C2
        // compiles a call it has not seen resolved as a trap: cold renders (with the start-up cache)
        // deoptimized trace at a still life's first mirror and the shadow walk at glass's
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
    private final ShadowRays shadows;
    private final int lightCount;
    /** Where this sample's shadow rays go on each light, and what camera and specular rays see of them. */
    private final LightSampler lightSampler;
    private final Emitters emitters;
    /**
     * Whether a sphere or area light is first tried whole ({@link WholeLitPoints}): where sampling
     * stops a pixel once its samples agree, a point that sees all of the light then has no noise
     * from it and needs no shadow ray; a pixel that takes all its samples whatever (a fixed sampler)
     * gains nothing for the try's cost. Set by the caller.
     */
    boolean wholeLights;
    private final WholeLitPoints wholeLit;
    /** The current sample's 2D point in [0, 1)^2 for its light samples; set by the caller. */
    double lightU = 0.5, lightV = 0.5;
    /** The direct light found by {@link #direct}. */
    private double directR, directG, directB;
    long rays;
    /**
     * Whether {@link #direct} asks, of each shadow ray to a sphere or area light that something
     * stopped, whether the point sees part of the light ({@link ShadowRays#seesPart}); set by the caller.
     */
    boolean watchPenumbrae;
    /**
     * Since the caller last cleared it: the most any such light could have added, unshadowed, to a
     * sample whose shadow ray to it went dark where the point may see part of the light
     * ({@link ShadowRays#seesPart}: a penumbra, where its one shadow ray went dark by chance); 0 if none.
     */
    double penumbraLight;
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
        this.lightCount = scene.lights().size();
        this.shadows = new ShadowRays(scene, minPathWeight);
        this.lightSampler = new LightSampler(scene.lights());
        this.emitters = new Emitters(scene.lights());
        this.wholeLit = new WholeLitPoints(scene);
    }

    /** Starts a run of samples of one pixel ({@link WholeLitPoints#startRun}). */
    void startRun() {
        wholeLit.startRun();
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
        rays++;
        int out = 3 * depth;
        Hit hit = hits[depth];
        boolean found = scene.intersect(ray, Double.POSITIVE_INFINITY, hit);
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
                    coneSpread * PathLength.to(hits, depth, ray, scene.camera().position()));
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

        shadows.cameraBundle = depth == 0 ? ray.bundle : null; // its shadow rays may share a pyramid
        direct(m, cr, cg, cb, hit, sx, sy, sz, -dx, -dy, -dz, front, weight);
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
                        double vx, double vy, double vz, boolean front, double weight) {
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
        for (int i = 0; i < lightCount; i++) {
            // a point that sees all of a light gets its diffuse part exact, and traces no shadow ray to it
            boolean lit = wholeLights && light.soft(i) && wholeLit.lit(i, hit, nx, ny, nz, front);
            if (lit && kd > 0) {
                r += ar * wholeLit.r;
                g += ag * wholeLit.g;
                b += ab * wholeLit.b;
            }
            if (lit && ks == 0) {
                continue; // no highlight to sample
            }
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
            boolean watch = watchPenumbrae && light.soft(i) && !lit;
            if (watch) {
                shadows.forgetBlocker(i);
            }
            boolean reached = lit || shadows.reach(i, hit, light.tx, light.ty, light.tz);
            rays += lit ? 0 : shadows.traced;
            if (!reached) {
                if (watch) {
                    // the light's diffuse part and its highlight at its brightest
                    double unshadowed = share * ((kd > 0 ? aMax * cos : 0) + sMax);
                    if (unshadowed > penumbraLight && shadows.seesPart(i, light)) {
                        penumbraLight = unshadowed;
                    }
                }
                continue;
            }
            if (!highlightDecides && ks > 0) {
                highlight = highlight(nx, ny, nz, lx, ly, lz, vx, vy, vz, m.shininess());
            }
            if (!lit) {
                er *= shadows.throughR;
                eg *= shadows.throughG;
                eb *= shadows.throughB;
                if (kd > 0) {
                    r += ar * er * cos;
                    g += ag * eg * cos;
                    b += ab * eb * cos;
                }
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
     * How many times a branch of path weight {@code w} at glass counts: 0 (not traced) when it is
     * too weak to change the pixel, else as its roulette decides (1 for a branch that is not weak).
     */
    private double branchCount(double w) {
        return w > minPathWeight ? roulette.factor(w) : 0;
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
            trace(Rays.spawn(hit, rx, ry, rz, childRays[depth]), depth + 1, wr * countR);
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
                trace(Rays.spawn(hit, tx, ty, tz, childRays[depth]), depth + 1, wt * countT);
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

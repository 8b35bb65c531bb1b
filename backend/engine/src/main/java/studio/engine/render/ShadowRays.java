package studio.engine.render;

import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.RayBundle;
import studio.engine.geometry.Rays;
import studio.engine.geometry.Shape;
import studio.engine.light.LightSampler;
import studio.engine.material.Fresnel;
import studio.engine.material.Material;
import studio.engine.material.MaterialKind;
import studio.engine.scene.Scene;
import studio.engine.scene.ShapeSet;

/**
 * Shadow rays for the {@link Integrator}: what fraction of a light reaches a point. A shadow ray
 * passes through glass surfaces, losing the Fresnel reflectance at each and taking the glass's
 * tint on the way in, so glass casts a lighter, tinted shadow. The light is assumed to go straight
 * through (no caustic focusing): a ray tracer that traces from the eye cannot find the bent path
 * to a point light, and a black shadow under clear glass looks more wrong than a light one.
 *
 * <p>One instance per worker thread, beside its integrator: it owns its hit record and ray.
 */
final class ShadowRays {

    /** At most this many glass surfaces are crossed by one shadow ray before it counts as blocked. */
    private static final int MAX_SHADOW_CROSSINGS = 32;
    /** A shadow ray is blocked only by hits closer than this fraction of the light's distance. */
    private static final double SHADOW_END = 1 - 1e-9;

    static {
        // resolved before the JIT compiles reach, as Integrator's static block explains: a cold
        // render otherwise deoptimizes reach at glass's first crossing
        Fresnel.reflectance(1, 1, 1.5);
    }

    private final Scene scene;
    private final double minPathWeight;
    /** The scene's opaque objects, and its glass ones (null: none). */
    private final ShapeSet opaque, glass;
    /** Per object, whether it is glass. */
    private final boolean[] isGlass;
    private final Hit shadowHit = new Hit();
    /** The rays {@link #seesPart} sends to the light's corners. */
    private final Ray probe = new Ray();
    /** Per light, the ray object of its shadow rays, which keeps what blocked the last one ({@link Ray#blocker}). */
    private final Ray[] shadowRays;
    /**
     * Per light, {@link #WAYS} bundles of shadow rays, each from where one camera bundle's rays hit
     * one object (picked by the object's index), which its shadow rays carry for the scene's
     * any-hit question; null for a light with a size, whose rays end all over it.
     */
    private final RayBundle[] lightBundles;
    /** Bundles kept per light: a pixel's rays may hit a few objects, each with its own pyramid to the light. */
    static final int WAYS = 4;
    /**
     * The bundle of the camera ray whose hit the next {@link #reach} leaves from (null: the hit is
     * not a camera ray's, or its ray has no bundle); set by the integrator.
     */
    RayBundle cameraBundle;
    /** The transmittance found by the last {@link #reach}, and how many rays it traced. */
    double throughR, throughG, throughB;
    int traced;

    ShadowRays(Scene scene, double minPathWeight) {
        this.scene = scene;
        this.minPathWeight = minPathWeight;
        this.opaque = scene.opaque();
        this.glass = scene.glass();
        this.isGlass = new boolean[scene.objectCount()];
        for (int i = 0; i < isGlass.length; i++) {
            isGlass[i] = scene.material(i).kind() == MaterialKind.GLASS;
        }
        this.shadowRays = new Ray[scene.lights().size()];
        this.lightBundles = new RayBundle[WAYS * shadowRays.length];
        for (int i = 0; i < shadowRays.length; i++) {
            shadowRays[i] = new Ray();
            for (int k = 0; k < WAYS && !scene.lights().get(i).soft(); k++) {
                lightBundles[WAYS * i + k] = RayBundle.towardsLight(scene.objectCount());
            }
        }
    }

    /**
     * What fraction of a light reaches the hit point, into throughR/G/B: 0 behind anything opaque,
     * less through glass. Returns false when nothing arrives. In a scene with glass the scene's
     * any-hit question decides first: nothing on the way, or an opaque object ({@link Ray#blocker}),
     * settles it in one question, as most shadow rays are (asking the opaque objects, then the glass,
     * for every ray took six-materials 1.08 times as long, warm).
     * Only a ray that meets glass asks the opaque objects, and then walks the glass objects surface
     * by surface, through their closest-hit question, multiplying their transmittance (the scene's
     * own closest-hit walk, with opaque objects in it, would make every blocked ray walk:
     * glass-pattern about 1.5 times as long).
     */
    boolean reach(int light, Hit from, double tx, double ty, double tz) {
        Ray shadowRay = shadowRays[light];
        Ray ray = Rays.spawnTowards(from, tx, ty, tz, shadowRay);
        double dist = distance(ray, tx, ty, tz);
        RayBundle bundle = lightBundles[WAYS * light + (from.primitive & (WAYS - 1))];
        if (cameraBundle != null && bundle != null) {
            ray.bundle = bundle.from(tx, ty, tz, cameraBundle, from.primitive);
        }
        traced = 1;
        throughR = throughG = throughB = 1;
        if (glass == null) {
            return !opaque.occluded(ray, dist * SHADOW_END);
        }
        if (!scene.occluded(ray, dist * SHADOW_END)) {
            return true;
        }
        ray.bundle = null; // the bundle serves the scene's question; the opaque and glass sets walk
        if (!isGlass[ray.blocker] || opaque.occluded(ray, dist * SHADOW_END)) {
            return false;
        }
        double r = 1, g = 1, b = 1;
        for (int crossing = 0; crossing < MAX_SHADOW_CROSSINGS; crossing++) {
            if (!glass.intersect(ray, dist * SHADOW_END, shadowHit)) {
                throughR = r;
                throughG = g;
                throughB = b;
                return true;
            }
            Material m = scene.material(shadowHit.primitive);
            double cos = shadowHit.nx * ray.dx + shadowHit.ny * ray.dy + shadowHit.nz * ray.dz;
            boolean entering = shadowHit.gx * ray.dx + shadowHit.gy * ray.dy + shadowHit.gz * ray.dz < 0;
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
            traced++;
        }
        return false;
    }

    /**
     * Makes the next {@link #reach} of light i walk without its last blocker ({@link Ray#blocker}), so
     * that the blocker it finds, which {@link #seesPart} judges, is the walk's own and not the last
     * ray's: an image must not depend on which rays a thread traced before.
     */
    void forgetBlocker(int light) {
        shadowRays[light].blocker = -1;
    }

    /**
     * After a {@link #reach} of light i that returned false: whether the point may see part of the
     * light, in a penumbra. So it does where the opaque object that stopped the ray is convex and does
     * not hide the whole light from the ray's origin ({@link LightSampler#hiddenBy}), and it may where
     * no opaque object did (glass dimmed the light to nothing). Not where a mesh stopped it: a mesh
     * need not be convex, so its corners tell nothing, and the pixel is judged by its neighbourhood
     * alone, as under a point light.
     */
    boolean seesPart(int light, LightSampler lights) {
        Ray ray = shadowRays[light];
        int blocker = ray.blocker;
        if (blocker < 0 || isGlass[blocker]) {
            return true;
        }
        Shape shape = scene.shape(blocker);
        return shape.convex() && !lights.hiddenBy(light, shape, ray.ox, ray.oy, ray.oz, probe);
    }

    private static double distance(Ray ray, double tx, double ty, double tz) {
        double x = tx - ray.ox, y = ty - ray.oy, z = tz - ray.oz;
        return Math.sqrt(x * x + y * y + z * z);
    }
}

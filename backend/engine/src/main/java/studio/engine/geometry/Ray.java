package studio.engine.geometry;

import studio.engine.accel.WideScratch;
import studio.engine.math.Vec3;

/**
 * A ray o + t*d. The direction need not be unit length; intersection tests accept any non-zero d.
 * Mutable so that the hot loop can reuse one per thread and recursion depth ({@link #set}, the
 * only way to change it); shapes only read it.
 */
public final class Ray {

    public double ox, oy, oz;
    public double dx, dy, dz;
    /**
     * The object whose surface the ray starts on, heading into it (-1: none, or not known): a
     * hint, as pbrt's ray carries its medium. A ray refracted into glass, or reflected inside it,
     * most likely leaves that object next, so the aggregate tests it first; any value gives the
     * same hit. Set by {@link Rays#spawn}, reset by {@link #set}.
     */
    public int within = -1;
    /**
     * The bundle of rays from one apex this ray belongs to (null: none), whose pyramid holds it:
     * the aggregate may test the ray against what it listed in the pyramid. Reset by {@link #set}.
     */
    public RayBundle bundle;
    /**
     * The object that blocked this ray object's last blocked any-hit question (-1: none): a hint
     * the aggregate tests first, as POV-Ray keeps a shadow cache per light (a renderer keeps one
     * ray object per light for its shadow rays). Kept by {@link #set}; any value gives the same answer.
     */
    public int blocker = -1;
    /** The ray in the triangle test's frame, set up on the first {@link #shear} after {@link #set}. */
    private final RayShear shear = new RayShear();
    private boolean sheared;
    /** Working memory of the scene's and a shape's wide any-hit walks, made on first use (kept by {@link #set}). */
    private WideScratch sceneWide, shapeWide;

    public Ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        set(ox, oy, oz, dx, dy, dz);
    }

    /**
     * The scene's wide any-hit walk's working memory (null where traversals walk binary trees,
     * {@link WideScratch#ifUsed}); made on the first call, so a ray that never meets a tree carries none.
     */
    public WideScratch sceneWide() {
        WideScratch s = sceneWide;
        return s != null ? s : (sceneWide = WideScratch.ifUsed());
    }

    /** As {@link #sceneWide}, for a walk inside one shape (a mesh's) while the scene's is in use. */
    public WideScratch shapeWide() {
        WideScratch s = shapeWide;
        return s != null ? s : (shapeWide = WideScratch.ifUsed());
    }

    /** A ray to be filled by {@link #set}. */
    public Ray() {
    }

    /** Makes this the ray o + t*d; returns this. */
    public Ray set(double ox, double oy, double oz, double dx, double dy, double dz) {
        this.ox = ox; this.oy = oy; this.oz = oz;
        this.dx = dx; this.dy = dy; this.dz = dz;
        within = -1;
        bundle = null;
        sheared = false;
        return this;
    }

    /** This ray in the watertight triangle test's frame, worked out once however many meshes it meets. */
    public RayShear shear() {
        if (!sheared) {
            shear.setUp(this);
            sheared = true;
        }
        return shear;
    }

    public Ray(Vec3 origin, Vec3 direction) {
        this(origin.x(), origin.y(), origin.z(), direction.x(), direction.y(), direction.z());
    }

    public Vec3 origin() {
        return new Vec3(ox, oy, oz);
    }

    public Vec3 direction() {
        return new Vec3(dx, dy, dz);
    }

    @Override
    public String toString() {
        return "Ray[o=(" + ox + ", " + oy + ", " + oz + "), d=(" + dx + ", " + dy + ", " + dz + ")]";
    }
}

package studio.engine.geometry;

import studio.engine.accel.Bvh;

/**
 * Rays inside one pyramid, which a ray may carry ({@link Ray#bundle}) so that the aggregate lists
 * once what the pyramid holds and tests each ray of it against that list instead of walking its
 * tree. Two kinds: the camera rays of a run of pixels, which leave the apex ({@link #aim}), and
 * the shadow rays from where those rays hit one object to a point light, which end at the apex
 * ({@link #towardsLight}; the aggregate makes their pyramid, from the light over the part of that
 * object's box inside the camera rays' pyramid). The aggregate keeps its list here, for as long as
 * the pyramid stays the same.
 */
public final class RayBundle {

    /** Most objects a camera bundle's list holds; with more, the rays walk the tree. */
    public static final int MAX = 32;
    /** Most objects a shadow bundle's list holds in any scene ({@link #shadowListMax}). */
    static final int SHADOW_MAX = 16;

    private final boolean fromApex;
    private final Frustum pyramid = new Frustum();
    private double ax, ay, az;
    /** The aggregate whose list this is (null: none yet for this pyramid), and the list. */
    public Object listedBy;
    public int count;
    public final int[] ids;
    public final double[] near;
    public final int[] stack = new int[Bvh.STACK_SIZE];
    /** A camera bundle's count of the pyramids it has had: a shadow bundle made from one of them knows it is gone. */
    private long version;
    /** A shadow bundle's camera bundle, that one's {@link #version}, and the object its rays leave. */
    private RayBundle source;
    private long sourceVersion;
    private int object;
    /** Scratch for the aggregate: the box a shadow bundle's pyramid is made over. */
    public final double[] box = new double[6];

    private RayBundle(boolean fromApex, int max) {
        this.fromApex = fromApex;
        this.ids = new int[max];
        this.near = new double[max];
    }

    /** A camera rays' bundle, for {@link #aim}. */
    public RayBundle() {
        this(true, MAX);
    }

    /** A bundle of shadow rays to one point light in a scene of this many objects, for {@link #from}. */
    public static RayBundle towardsLight(int objects) {
        return new RayBundle(false, shadowListMax(objects));
    }

    /**
     * The longest list of a shadow bundle worth testing among n objects: log2 n rounded down, at
     * most {@value #SHADOW_MAX}. A shadow ray tests its list whole (any hit, no nearest-first
     * cut), and a walk of the tree tests about two boxes at each of its log2 n levels; an object
     * costs about as much as two boxes.
     */
    public static int shadowListMax(int objects) {
        return objects <= 1 ? 0 : Math.min(SHADOW_MAX, 31 - Integer.numberOfLeadingZeros(objects));
    }

    /** Whether the rays leave the apex (camera rays) rather than end at it (shadow rays). */
    public boolean fromApex() {
        return fromApex;
    }

    /** A new pyramid with its apex at (x, y, z), for the caller to set; forgets the list. */
    public Frustum aim(double x, double y, double z) {
        ax = x;
        ay = y;
        az = z;
        listedBy = null;
        version++;
        return pyramid;
    }

    /**
     * Makes this shadow bundle the one of the rays to the light at (x, y, z) from where the rays
     * of camera bundle {@code camera} hit object {@code object}, forgetting its list unless it
     * already is; returns this. Its pyramid is the aggregate's to make.
     */
    public RayBundle from(double x, double y, double z, RayBundle camera, int object) {
        if (camera != source || camera.version != sourceVersion || object != this.object
                || x != ax || y != ay || z != az) {
            source = camera;
            sourceVersion = camera.version;
            this.object = object;
            ax = x;
            ay = y;
            az = z;
            listedBy = null;
        }
        return this;
    }

    /** A shadow bundle's camera bundle. */
    public RayBundle source() {
        return source;
    }

    /** The object a shadow bundle's rays leave from. */
    public int object() {
        return object;
    }

    public Frustum pyramid() {
        return pyramid;
    }

    public double apexX() {
        return ax;
    }

    public double apexY() {
        return ay;
    }

    public double apexZ() {
        return az;
    }
}

package studio.engine.geometry;

import studio.engine.accel.Bvh;

/**
 * Rays from one apex inside one pyramid (the camera rays of a run of pixels), which a ray may
 * carry ({@link Ray#bundle}) so that the aggregate lists once what the pyramid holds and tests
 * each ray of it against that list instead of walking its tree. One per worker thread: the
 * aggregate keeps its list here, for as long as the pyramid stays the same.
 */
public final class RayBundle {

    /** Most objects a list holds; with more, the rays walk the tree. */
    public static final int MAX = 32;

    private final Frustum pyramid = new Frustum();
    private double ax, ay, az;
    /** The aggregate whose list this is (null: none yet for this pyramid), and the list. */
    public Object listedBy;
    public int count;
    public final int[] ids = new int[MAX];
    public final double[] near = new double[MAX];
    public final int[] stack = new int[Bvh.STACK_SIZE];

    /** A new pyramid with its apex at (x, y, z), for the caller to set; forgets the list. */
    public Frustum aim(double x, double y, double z) {
        ax = x;
        ay = y;
        az = z;
        listedBy = null;
        return pyramid;
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

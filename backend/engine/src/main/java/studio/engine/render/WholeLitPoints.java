package studio.engine.render;

import studio.engine.accel.Bvh;
import studio.engine.geometry.Frustum;
import studio.engine.geometry.Hit;
import studio.engine.light.WholeLight;
import studio.engine.scene.Scene;

/**
 * For the {@link Integrator}: whether a point sees all of a sphere or area light, and then what
 * all of it gives the point. So it does where the light lies wholly above the point's horizon and
 * no object but a convex one the point lies on may meet the pyramid from the point to the light
 * ({@link WholeLight#whole}, {@link Scene#nothingIn}): such a point needs no shadow ray, and its
 * diffuse light is worked out, not sampled, so it has no noise.
 *
 * <p>After one point of a run of a pixel's samples ({@link #startRun}) fails, the run's later
 * points sample that light without trying: a shadowed pixel pays for the try once. Which points
 * are tried depends on the run's own samples alone, so the image does not depend on the threads.
 *
 * <p>One per worker thread, beside its integrator; it allocates nothing after construction.
 */
final class WholeLitPoints {

    private final Scene scene;
    private final WholeLight whole;
    /** The pyramid to the light, its bounding box, and its walk's stack. */
    private final Frustum pyramid = new Frustum();
    private final double[] reach = new double[6];
    private final int[] stack = new int[Bvh.STACK_SIZE];
    /** Per light: the last run in which a point could not be shown to see all of it. */
    private final long[] failedIn;
    /** The run of samples being traced. */
    private long run;
    /** What all of the light gives the point, per channel, its cosine included: set by a true {@link #lit}. */
    double r, g, b;

    WholeLitPoints(Scene scene) {
        this.scene = scene;
        this.whole = new WholeLight(scene.lights());
        this.failedIn = new long[scene.lights().size()];
        this.run = 1;
    }

    /** Starts a run of samples of one pixel: every light is tried again. */
    void startRun() {
        run++;
    }

    /**
     * Whether the hit point, with shading normal (nx, ny, nz) turned to the side the ray came from
     * ({@code front}: the geometric normal's side), sees all of sphere or area light i; if so, sets
     * r, g, b to its diffuse light. False, untried, after a failed try of this run.
     */
    boolean lit(int i, Hit hit, double nx, double ny, double nz, boolean front) {
        if (failedIn[i] == run) {
            return false;
        }
        double side = front ? 1 : -1;
        boolean lit = whole.whole(i, hit.px, hit.py, hit.pz, nx, ny, nz, side * hit.gx, side * hit.gy, side * hit.gz,
                pyramid)
                // a convex surface, the light above its tangent plane there, does not stand in the way
                && scene.nothingIn(pyramid, scene.shape(hit.primitive).convex() ? hit.primitive : -1, reach, stack);
        if (!lit) {
            failedIn[i] = run;
            return false;
        }
        whole.light(i);
        r = whole.r;
        g = whole.g;
        b = whole.b;
        return true;
    }
}

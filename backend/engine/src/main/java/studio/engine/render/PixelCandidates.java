package studio.engine.render;

import java.util.Arrays;

import studio.engine.accel.Bvh;
import studio.engine.geometry.Frustum;
import studio.engine.math.Vec3;
import studio.engine.scene.Scene;

/**
 * The objects one pixel's samples can meet, found once for all of them: a pixel's camera rays
 * all lie in one thin pyramid from the camera, and the shadow rays from where they hit to a light
 * in one from the light. A BVH traversal with each pyramid ({@link Scene#candidates}) lists the
 * few objects inside it, and each ray then tests only those, in declaration order, instead of
 * searching the BVH. The pixels are the same to the bit (a ray can hit only what lies in its
 * pyramid, and the tie rule picks the same winner in declaration order).
 *
 * <p>Measured with 10,000 spheres at 16 samples a pixel, where most camera rays pass between
 * spheres deep into the tree and most of a pixel's 16 rays meet the same one or two spheres; see
 * docs/speed.md for the figures. It pays only when a pixel has several samples, and only camera
 * rays and the shadow rays from their hits use it: reflected and refracted rays go their own ways.
 *
 * <p>The pyramid for a light holds every segment from the light to a box of all the pixel's
 * possible hit points ({@link Frustum#overBox}): the camera candidates' boxes, and for a plane its
 * part inside the camera rays' pyramid. Where that part is unbounded (the pixel sees the horizon)
 * shadow rays search the whole scene.
 */
final class PixelCandidates {

    /** Most objects a pyramid may hold; with more, the rays search the BVH. */
    static final int MAX = 16;
    /** A light's list not yet worked out for this pixel. */
    private static final int UNKNOWN = -2;

    private final Scene scene;
    private final Frustum frustum = new Frustum();
    private final int[] stack = new int[Bvh.STACK_SIZE];
    /** The objects the camera rays can hit, ascending; {@link #cameraCount} of them, or -1: all. */
    final int[] camera = new int[MAX];
    int cameraCount = -1;
    /** Per light, the objects that can shadow a camera ray's hit, as {@link #camera}. */
    private final int[][] shadow;
    private final int[] shadowCount;
    /** The box of every point where the camera rays can hit, if {@link #hitsBounded}. */
    private final double[] hitBox = new double[6];
    private boolean hitsBounded;

    PixelCandidates(Scene scene) {
        this.scene = scene;
        int lights = scene.lights().size();
        shadow = new int[lights][MAX];
        shadowCount = new int[lights];
        none();
    }

    /** From now on camera rays lie inside {@code cameraRays}; lists what they can hit. */
    void forCameraRaysIn(Frustum cameraRays) {
        cameraCount = scene.candidates(cameraRays, camera, stack);
        hitsBounded = cameraCount > 0 && scene.boundsOf(camera, cameraCount, cameraRays, hitBox);
        Arrays.fill(shadowCount, hitsBounded ? UNKNOWN : -1);
    }

    /** From now on camera rays may go anywhere: every ray searches the whole scene. */
    void none() {
        cameraCount = -1;
        hitsBounded = false;
        Arrays.fill(shadowCount, -1);
    }

    /**
     * How many objects can shadow a camera ray's hit from light i (listed in {@link #shadow}), or
     * -1 to search the whole scene. Worked out on the first call for each light.
     */
    int shadowCount(int light) {
        if (shadowCount[light] == UNKNOWN) {
            Vec3 at = scene.lights().get(light).position();
            shadowCount[light] = frustum.overBox(at.x(), at.y(), at.z(), hitBox)
                    ? scene.candidates(frustum, shadow[light], stack) : -1;
        }
        return shadowCount[light];
    }

    int[] shadow(int light) {
        return shadow[light];
    }
}

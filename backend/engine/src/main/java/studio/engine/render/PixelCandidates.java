package studio.engine.render;

import java.util.Arrays;

import studio.engine.accel.Bvh;
import studio.engine.geometry.Frustum;
import studio.engine.math.Vec3;
import studio.engine.scene.Scene;

/**
 * The objects one pixel's samples can meet, found once for all of them (and for a few pixels
 * beside it in its row: {@link SampleTracer#LIST_RUN}): a pixel's camera rays all lie in one thin
 * pyramid from the camera, and the shadow rays from where they hit to a light in one from the
 * light. A BVH traversal with each pyramid ({@link Scene#candidates}) lists the
 * few objects inside it, and each ray then tests only those instead of searching the BVH. The
 * pixels are the same to the bit (a ray can hit only what lies in its pyramid, and the tie rule
 * picks the same winner in any order of testing).
 *
 * <p>The camera list is ordered by each object's distance from the camera
 * ({@link Scene#orderByDistance}), and a camera ray stops at the first object that lies beyond its
 * best hit, as the tree's search skips the boxes beyond it ({@link Scene#intersectNearFirst}). So
 * the list may hold many objects ({@link #CAMERA_MAX}): a ray into a cloud tests the few in front
 * and stops. A shadow ray stops at any object on its way, not the nearest, so a light's list is
 * tested whole and stays short ({@link #longest}).
 *
 * <p>It pays most where camera rays pass between many objects deep into the tree and a pixel's
 * rays meet the same one or two (10,000 spheres at 16 samples a pixel: see docs/speed.md), also in
 * scenes of a few objects, and only when a pixel has several samples. Only camera rays and the
 * shadow rays from their hits use it: reflected and refracted rays go their own ways.
 *
 * <p>The pyramid for a light holds every segment from the light to a box of all the pixel's
 * possible hit points ({@link Frustum#overBox}, {@link Scene#boundsOf}): the part of each camera
 * candidate's box inside the camera rays' pyramid, and for a plane its part inside that pyramid.
 * Where a plane's part is unbounded (the pixel sees its horizon), or the camera list is longer
 * than a light's may be, shadow rays search the whole scene.
 */
final class PixelCandidates {

    /**
     * Fewest objects for which listing pays. Measured as users meet it, whole {@code bin/studio}
     * processes at 800x600 and 16 samples, alternated: with lists the still life (6 objects) took
     * 1.09 of the time without, though warm, one thread, 0.94: a render of a second or two spends
     * much of it before the JIT has compiled the pyramids' code, and a small tree leaves little to
     * save. From 8 objects on, with lists no longer than {@link #longest}, warm renders gain (see
     * there) and whole processes lose nothing.
     */
    static final int MIN_OBJECTS = 8;

    /** Most objects a light's list may hold in any scene; with more, the shadow rays search the BVH. */
    static final int MAX = 16;
    /**
     * Most objects a camera list may hold; with more, the camera rays search the BVH. Its rays
     * test only the nearest few, so its length matters little: warm, 800x600, 16 jittered samples,
     * 2 threads, 8,000 random spheres over a floor (lists of at most 12 before, in declaration
     * order, tested whole) took 0.81-0.91 of the time with lists of at most 24, 48, 96 or 160
     * alike (one or two alternated pairs each); glass-pattern (16 objects) the same with 4 or 16.
     */
    static final int CAMERA_MAX = 32;
    /** A light's list not yet worked out for this pixel. */
    private static final int UNKNOWN = -2;

    private final Scene scene;
    private final Frustum frustum = new Frustum();
    private final int[] stack = new int[Bvh.STACK_SIZE];
    /**
     * The objects the camera rays can hit, nearest first; {@link #cameraCount} of them, or -1: all.
     * {@link #cameraNear} holds a bound below each one's distance along a camera ray.
     */
    final int[] camera;
    final double[] cameraNear;
    int cameraCount = -1;
    /** The longest list a light may have in this scene ({@link #longest}). */
    private final int longest;
    /** Per light, the objects that can shadow a camera ray's hit, ascending. */
    private final int[][] shadow;
    private final int[] shadowCount;
    /** A box of every point where the camera rays can hit, while a light's list is {@link #UNKNOWN}. */
    private final double[] hitBox = new double[6];

    /**
     * Whether listing pays for this scene: one searched through a BVH of {@value #MIN_OBJECTS}
     * objects or more, whose planes (in every list) leave room for others in a list of
     * {@link #longest} objects.
     */
    static boolean pay(Scene scene) {
        return scene.searchesBvh() && scene.objectCount() >= MIN_OBJECTS
                && scene.unboundedCount() < longest(scene.objectCount());
    }

    /**
     * The longest list of a light worth testing among n objects: log2 n rounded down, at most {@value #MAX}
     * (0 for an empty scene). A ray's search of the tree tests about two boxes at each of its
     * log2 n levels, and testing an object costs about as much as two boxes, so a longer list costs
     * more than the search it spares (whole processes against no lists: glass-pattern 0.95 of the
     * time, six-materials 0.96; lists of up to 16: 1.02; docs/speed.md).
     */
    static int longest(int objects) {
        return objects <= 0 ? 0 : Math.min(MAX, 31 - Integer.numberOfLeadingZeros(objects));
    }

    PixelCandidates(Scene scene) {
        this.scene = scene;
        int lights = scene.lights().size();
        longest = longest(scene.objectCount());
        camera = new int[Math.min(CAMERA_MAX, scene.objectCount())];
        cameraNear = new double[camera.length];
        shadow = new int[lights][longest];
        shadowCount = new int[lights];
        Arrays.fill(shadowCount, -1);
    }

    /** From now on camera rays lie inside {@code cameraRays}; lists what they can hit. */
    void forCameraRaysIn(Frustum cameraRays) {
        cameraCount = scene.candidates(cameraRays, camera, stack);
        if (cameraCount > 0) {
            Vec3 at = scene.camera().position();
            scene.orderByDistance(camera, cameraCount, at.x(), at.y(), at.z(), cameraNear);
        }
        // a long camera list makes a wide box, and a light's pyramid over it would overflow its list
        boolean hitsBounded = cameraCount > 0 && cameraCount <= longest
                && scene.boundsOf(camera, cameraCount, cameraRays, hitBox);
        Arrays.fill(shadowCount, hitsBounded ? UNKNOWN : -1);
    }

    /** From now on camera rays may go anywhere: every ray searches the whole scene. */
    void none() {
        if (cameraCount < 0) {
            return; // no camera list, so no shadow lists either
        }
        cameraCount = -1;
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

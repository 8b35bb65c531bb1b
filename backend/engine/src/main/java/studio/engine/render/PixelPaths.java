package studio.engine.render;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import studio.engine.accel.Aabb;
import studio.engine.geometry.Shape;
import studio.engine.geometry.Sphere;
import studio.engine.light.Light;
import studio.engine.math.Vec3;

/**
 * Where each pixel's rays went in a render of one sample a pixel, kept with its film so that a
 * render of an edited scene into the same film can keep every pixel the edit cannot reach and
 * render only the others (a live view's drag moves one object; most of the image stays as it
 * was).
 *
 * <p>A pixel's one sample is a chain of rays: the camera ray, then what a mirror reflects, up to
 * {@value #MAX_POINTS} rays. Kept are the points where they end (a hit, or for a ray that leaves
 * the scene its direction), as floats. Its value depends only on the objects those rays and the
 * shadow rays from each hit point to each light meet, so it stays the same when every changed
 * object (before and after the change) lies off all of those segments: {@link #forget} tests
 * them against the changed objects' boxes, and a sphere's ball ({@link #forgetShapes}), widened
 * far beyond the floats' rounding ({@link EditReach}). A pixel whose
 * rays branch (glass both reflects and refracts), that traces a longer chain, or that takes more
 * than one sample is not kept: it is rendered every time.
 *
 * <p>An edit rebuilds the scene's tree, and the hit chosen among near-ties
 * ({@link studio.engine.scene.Scene#TIE}) does not depend on the tree for hits that form separate
 * clusters, so a kept pixel is the pixel a render of the edited scene gives, to the bit
 * (PixelPathsTest renders both and compares); only a chain of near-ties spread over more than the
 * tie distance could resolve differently (see {@link studio.engine.scene.ShapeSet}).
 *
 * <p>{@link #forget} only notes an edit; each pixel is tested against the edits made since its
 * render when a render next comes to it (in the render's threads, and only for the pixels that
 * render asks for: a coarse pass of a live view tests one pixel in 64). At most
 * {@value #MAX_EDITS} edits are noted: a pixel older than those is rendered again. Each pixel is
 * written by the one thread that renders it; {@link #forget} and {@link #forgetAll} run between
 * renders.
 */
public final class PixelPaths {

    /** The longest chain of rays a kept pixel may trace. */
    public static final int MAX_POINTS = 3;
    /** Bytes per pixel: the points' floats, a state byte and the edit it was last tested against. */
    public static final int BYTES_PER_PIXEL = 3 * 4 * MAX_POINTS + 1 + 4;
    /** Edits noted and not yet tested on every pixel: a pixel rendered before the oldest is forgotten. */
    static final int MAX_EDITS = 8;
    /**
     * An edit of more boxes than this (8 objects, before and after) forgets every pixel: each
     * segment is tested against each box, and at 16 boxes the tests cost about a third of the
     * one-sample render they save (the 10,000 spheres at 640x480, one thread).
     */
    static final int MAX_BOXES = 16;

    /** Not rendered since it was forgotten (or never): the next render renders it. */
    private static final byte UNKNOWN = -1;
    /** Being rendered, and its rays do not form a chain that can be kept. */
    private static final byte UNKEPT = -2;
    /** In a state of 1 or more: the low bits count the points, this bit marks the last as a direction. */
    private static final int MISS = 8;
    private static final int COUNT = 7;
    /** The segments' margin as a share of the largest coordinate involved (floats round to 6e-8 of it). */
    private static final double MARGIN = 1e-5;

    private final int width, height;
    private final float[] points;
    private final byte[] state;
    /** Per pixel, the edit number it was rendered at or last tested against. */
    private final int[] tested;
    /** The edits noted, oldest first, numbered {@code edit - edits.length + 1 .. edit}. */
    private Edit[] edits = new Edit[0];
    /** The number of the last edit noted; pixels tested against it are up to date. */
    private int edit;

    public PixelPaths(int width, int height) {
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("pixel paths need at least 1x1 pixels: " + width + "x" + height);
        }
        this.width = width;
        this.height = height;
        this.points = new float[3 * MAX_POINTS * width * height];
        this.state = new byte[width * height];
        this.tested = new int[width * height];
        Arrays.fill(state, UNKNOWN);
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /**
     * Whether pixel (x, y) holds a kept render that no edit since has reached, testing it against
     * the edits noted since (and forgetting it if one may reach it).
     */
    public boolean known(int x, int y) {
        return known(y * width + x);
    }

    private boolean known(int p) {
        int s = state[p];
        if (s <= 0) {
            return false;
        }
        int since = tested[p];
        if (since == edit) {
            return true;
        }
        int first = edit - edits.length + 1;
        if (since < first - 1) {
            state[p] = UNKNOWN; // older than the edits noted
            return false;
        }
        for (int e = since + 1; e <= edit; e++) {
            if (edits[e - first].reaches(this, p, s)) {
                state[p] = UNKNOWN;
                return false;
            }
        }
        tested[p] = edit;
        return true;
    }

    /** Forgets every pixel: after an edit that may reach all of them (the camera, a light, the size). */
    public void forgetAll() {
        Arrays.fill(state, UNKNOWN);
        edits = new Edit[0];
    }

    /**
     * Notes an edit: a known pixel is forgotten (when a render next asks for it) if one of the
     * boxes may change it: if its camera ray, its later rays or a shadow ray from one of its hit
     * points to a light may meet a box. More than {@value #MAX_BOXES} boxes forget every pixel now.
     *
     * @param boxes  the changed objects' boxes, each object's before and after the edit (bounded)
     * @param camera the camera's position, where every pixel's first ray starts
     * @param lights the scene's lights (unchanged by the edit); with a sphere or area light among
     *               them every pixel is forgotten, as its shadow rays end all over the light
     */
    public void forget(List<Aabb> boxes, Vec3 camera, List<? extends Light> lights) {
        forget(boxes, new double[0], camera, lights);
    }

    /**
     * As {@link #forget(List, Vec3, List)} with the changed objects' shapes (each object's before
     * and after the edit), so that a segment that meets a sphere's box but passes beside the sphere
     * keeps its pixel: most of those that only pass near a moved ball (docs/live-view.md).
     */
    public void forgetShapes(List<? extends Shape> shapes, Vec3 camera, List<? extends Light> lights) {
        List<Aabb> boxes = new ArrayList<>(shapes.size());
        double[] balls = new double[4 * shapes.size()];
        for (int i = 0; i < shapes.size(); i++) {
            Shape shape = shapes.get(i);
            boxes.add(shape.bounds());
            if (shape instanceof Sphere sphere) {
                balls[4 * i] = sphere.center().x();
                balls[4 * i + 1] = sphere.center().y();
                balls[4 * i + 2] = sphere.center().z();
                balls[4 * i + 3] = sphere.radius();
            } else {
                balls[4 * i + 3] = -1;
            }
        }
        forget(boxes, balls, camera, lights);
    }

    /** As {@link #forget(List, Vec3, List)}, each box's object held by the ball at balls[4 i ..] if its radius is not negative. */
    private void forget(List<Aabb> boxes, double[] balls, Vec3 camera, List<? extends Light> lights) {
        if (boxes.isEmpty()) {
            return;
        }
        if (boxes.size() > MAX_BOXES || lights.stream().anyMatch(Light::soft)) {
            forgetAll();
            return;
        }
        double[] box = new double[6 * (boxes.size() + 1)];
        double[] ball = new double[4 * (boxes.size() + 1)];
        double scale = Math.max(Math.abs(camera.x()), Math.max(Math.abs(camera.y()), Math.abs(camera.z())));
        boolean everyBall = true;
        for (int i = 0; i < boxes.size(); i++) {
            Aabb b = boxes.get(i);
            if (!b.isBounded()) {
                throw new IllegalArgumentException("an unbounded object's edit reaches every pixel: forget them all");
            }
            b.copyTo(box, 6 * (i + 1));
            boolean held = 4 * i < balls.length && balls[4 * i + 3] >= 0;
            everyBall &= held;
            if (held) {
                System.arraycopy(balls, 4 * i, ball, 4 * (i + 1), 4);
            } else {
                ball[4 * (i + 1) + 3] = -1;
            }
        }
        // box 0: the union, tested first; its ball holds every object's, if each has one
        for (int k = 0; k < 3; k++) {
            double min = Double.POSITIVE_INFINITY, max = Double.NEGATIVE_INFINITY;
            for (int i = 1; i <= boxes.size(); i++) {
                min = Math.min(min, box[6 * i + k]);
                max = Math.max(max, box[6 * i + k + 3]);
            }
            box[k] = min;
            box[k + 3] = max;
            ball[k] = (min + max) / 2;
            scale = Math.max(scale, Math.max(Math.abs(min), Math.abs(max)));
        }
        ball[3] = -1;
        if (everyBall) {
            double radius = 0;
            for (int i = 1; i <= boxes.size(); i++) {
                double dx = ball[4 * i] - ball[0], dy = ball[4 * i + 1] - ball[1], dz = ball[4 * i + 2] - ball[2];
                radius = Math.max(radius, Math.sqrt(dx * dx + dy * dy + dz * dz) + ball[4 * i + 3]);
            }
            ball[3] = radius * (1 + 1e-9);
        }
        double[] light = new double[3 * lights.size()];
        for (int i = 0; i < lights.size(); i++) {
            Vec3 at = lights.get(i).position();
            light[3 * i] = at.x();
            light[3 * i + 1] = at.y();
            light[3 * i + 2] = at.z();
            scale = Math.max(scale, Math.max(Math.abs(at.x()), Math.max(Math.abs(at.y()), Math.abs(at.z()))));
        }
        EditReach reach = new EditReach(box, ball, boxes.size() > 1, scale, MARGIN);
        EditReach.Cone[] cones = new EditReach.Cone[1 + lights.size()];
        cones[0] = reach.cone(camera.x(), camera.y(), camera.z());
        for (int l = 0; l < lights.size(); l++) {
            cones[1 + l] = reach.cone(light[3 * l], light[3 * l + 1], light[3 * l + 2]);
        }
        int kept = Math.min(edits.length, MAX_EDITS - 1);
        Edit[] next = Arrays.copyOfRange(edits, edits.length - kept, edits.length + 1);
        next[kept] = new Edit(reach, cones, camera.x(), camera.y(), camera.z(), light);
        edits = next;
        edit++;
    }

    /** One edit noted: its boxes, the cones around them from the camera and each light, and where those are. */
    private record Edit(EditReach reach, EditReach.Cone[] cones, double cx, double cy, double cz, double[] light) {

        /** Whether pixel p's rays (state s) may meet one of the edit's boxes. */
        boolean reaches(PixelPaths paths, int p, int s) {
            return paths.reaches(reach, cones, p, s, cx, cy, cz, light);
        }
    }

    /** Whether pixel p's rays (state s) may meet a changed box. */
    private boolean reaches(EditReach reach, EditReach.Cone[] cones, int p, int s, double ax, double ay, double az,
                            double[] light) {
        int count = s & COUNT;
        boolean lastMisses = (s & MISS) != 0;
        int o = 3 * MAX_POINTS * p;
        for (int i = 0; i < count; i++, o += 3) {
            double bx = points[o], by = points[o + 1], bz = points[o + 2];
            if (i == count - 1 && lastMisses) {
                return reach.meets(ax, ay, az, bx, by, bz, Double.POSITIVE_INFINITY);
            }
            if ((i > 0 || cones[0].mayMeet(bx, by, bz)) && reach.meets(ax, ay, az, bx - ax, by - ay, bz - az, 1)) {
                return true;
            }
            for (int l = 0; l < light.length; l += 3) {
                if (cones[1 + l / 3].mayMeet(bx, by, bz)
                        && reach.meets(bx, by, bz, light[l] - bx, light[l + 1] - by, light[l + 2] - bz, 1)) {
                    return true;
                }
            }
            ax = bx;
            ay = by;
            az = bz;
        }
        return false;
    }

    /** Starts recording pixel p's rays (the renderer, before its samples). */
    void start(int p) {
        state[p] = 0;
    }

    /**
     * Records where a ray at recursion {@code depth} of the pixel being rendered ended: its hit
     * point, or with {@code miss} its direction.
     */
    void record(int p, int depth, double x, double y, double z, boolean miss) {
        int s = state[p];
        if (s < 0) {
            return;
        }
        int count = s & COUNT;
        if (depth != count || count == MAX_POINTS || (s & MISS) != 0) {
            state[p] = UNKEPT; // a branch, a second sample, or a longer chain
            return;
        }
        int o = 3 * (MAX_POINTS * p + count);
        points[o] = (float) x;
        points[o + 1] = (float) y;
        points[o + 2] = (float) z;
        state[p] = (byte) ((count + 1) | (miss ? MISS : 0));
    }

    /** Ends pixel p's recording once its value is in the film: known if its rays were kept. */
    void finish(int p) {
        if (state[p] <= 0) {
            state[p] = UNKNOWN;
        } else {
            tested[p] = edit;
        }
    }

    int index(int x, int y) {
        return y * width + x;
    }
}

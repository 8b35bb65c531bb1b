package studio.engine.scene;

import java.util.List;

import studio.engine.accel.ShapeLeaves;
import studio.engine.camera.Camera;
import studio.engine.geometry.Frustum;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Shape;
import studio.engine.light.Light;
import studio.engine.material.Material;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;

/**
 * Everything a render reads: camera, objects in declaration order, lights, background and ambient
 * term. Built once, then only read (by every worker thread at once). Its objects form an
 * aggregate ({@link ShapeSet}) that answers two questions, {@link #intersect} and
 * {@link #occluded}; for shadow rays its opaque and its glass objects form one each.
 */
public final class Scene {

    /** Hits whose distances differ by at most this fraction are a tie; the first-declared object wins. */
    public static final double TIE = ShapeLeaves.TIE;

    private final Camera camera;
    private final Shape[] shapes;
    private final ShapeSet geometry;
    /** The opaque objects and the glass ones (null: no glass, and then {@link #opaque} is {@link #geometry}). */
    private final ShapeSet opaque, glass;
    private final Material[] materials;
    private final List<Light> lights;
    private final Rgb background;
    private final double ambient;

    public Scene(Camera camera, List<SceneObject> objects, List<? extends Light> lights, Rgb background, double ambient) {
        this(camera, objects, lights, background, ambient, null);
    }

    /**
     * The scene the constructor builds from these parts, its aggregates' trees refitted from
     * {@code last}'s where it has as many objects and all but a few of its shapes are the very
     * objects of {@code last}'s at the same places (a live view's next revision): the same hits,
     * 10,001 objects in about 1.5 ms of CPU time instead of 11-13 ({@link ShapeTree}).
     */
    public static Scene reusing(Scene last, Camera camera, List<SceneObject> objects, List<? extends Light> lights,
                                Rgb background, double ambient) {
        return new Scene(camera, objects, lights, background, ambient, last);
    }

    private Scene(Camera camera, List<SceneObject> objects, List<? extends Light> lights, Rgb background, double ambient,
                  Scene last) {
        if (camera == null || objects == null || lights == null || background == null) {
            throw new IllegalArgumentException("camera, objects, lights and background are required");
        }
        if (!(background.r() >= 0 && background.g() >= 0 && background.b() >= 0)
                || !Double.isFinite(background.max())) {
            throw new IllegalArgumentException("background must be finite and non-negative: " + background);
        }
        if (!(ambient >= 0) || !Double.isFinite(ambient)) {
            throw new IllegalArgumentException("ambient must be finite and non-negative: " + ambient);
        }
        this.camera = camera;
        this.shapes = objects.stream().map(SceneObject::shape).toArray(Shape[]::new);
        this.materials = objects.stream().map(SceneObject::material).toArray(Material[]::new);
        // light buffers for point lights only (null for a light with a size), where shadow rays go: see ShapeSet
        List<Vec3> buffered = lights.stream().map(l -> l.soft() ? null : l.position()).toList();
        boolean[] isGlass = new boolean[shapes.length], isOpaque = new boolean[shapes.length];
        boolean anyGlass = false;
        for (int i = 0; i < shapes.length; i++) {
            isGlass[i] = materials[i].kind() == MaterialKind.GLASS;
            isOpaque[i] = !isGlass[i];
            anyGlass |= isGlass[i];
        }
        this.geometry = ShapeSet.of(buffered, shapes, last != null ? last.geometry : null);
        if (anyGlass) {
            this.opaque = ShapeSet.of(buffered, shapes, isOpaque, false, last != null ? last.opaque : null);
            // a tree even for one object: most shadow rays miss the glass, and its box says so quickest
            this.glass = ShapeSet.of(List.of(), shapes, isGlass, true, last != null ? last.glass : null);
        } else {
            this.opaque = geometry;
            this.glass = null;
        }
        this.lights = List.copyOf(lights);
        this.background = background;
        this.ambient = ambient;
    }

    /**
     * The nearest hit with 0 &lt; t &lt; tMax, its primitive index set. Of hits within {@link #TIE}
     * of each other the first-declared object wins, so coincident surfaces never speckle.
     */
    public boolean intersect(Ray ray, double tMax, Hit hit) {
        return geometry.intersect(ray, tMax, hit);
    }

    /** Whether anything lies on the ray with 0 &lt; t &lt; tMax. */
    public boolean occluded(Ray ray, double tMax) {
        return geometry.occluded(ray, tMax);
    }

    /** Whether no object but object {@code except} (-1: none) may lie in the pyramid ({@link ShapeSet#nothingIn}). */
    public boolean nothingIn(Frustum pyramid, int except, double[] reach, int[] stack) {
        return geometry.nothingIn(pyramid, except, reach, stack);
    }

    /**
     * The scene's opaque objects, an aggregate of their own: a shadow ray is blocked exactly when
     * it says so; one that meets glass ({@link #occluded} names it) asks it, then the glass
     * ({@link #glass}) when it is not blocked. Hits report an object's index in the scene.
     */
    public ShapeSet opaque() {
        return opaque;
    }

    /** The scene's glass objects, an aggregate of their own (see {@link #opaque}), or null: the scene has none. */
    public ShapeSet glass() {
        return glass;
    }

    public Camera camera() {
        return camera;
    }

    public int objectCount() {
        return shapes.length;
    }

    public Shape shape(int index) {
        return shapes[index];
    }

    public Material material(int index) {
        return materials[index];
    }

    public List<Light> lights() {
        return lights;
    }

    public Rgb background() {
        return background;
    }

    public double ambient() {
        return ambient;
    }
}

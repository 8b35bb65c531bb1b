package studio.engine.scene;

import java.util.List;

import studio.engine.camera.Camera;
import studio.engine.geometry.Frustum;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Shape;
import studio.engine.light.Light;
import studio.engine.material.Material;
import studio.engine.math.Rgb;

/**
 * Everything a render reads: camera, objects in declaration order, lights, background and ambient
 * term. Built once, then only read (by every worker thread at once).
 */
public final class Scene {

    /** Hits whose distances differ by at most this fraction are a tie; the first-declared object wins. */
    public static final double TIE = 1e-9;

    private final Camera camera;
    private final Shape[] shapes;
    private final ShapeSet geometry;
    private final Material[] materials;
    private final List<Light> lights;
    private final Rgb background;
    private final double ambient;

    public Scene(Camera camera, List<SceneObject> objects, List<? extends Light> lights, Rgb background, double ambient) {
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
        // light buffers for point lights only (null for a light with a size): see ShapeSet
        this.geometry = ShapeSet.of(lights.stream().map(l -> l.soft() ? null : l.position()).toList(), shapes);
        this.materials = objects.stream().map(SceneObject::material).toArray(Material[]::new);
        this.lights = List.copyOf(lights);
        this.background = background;
        this.ambient = ambient;
    }

    /**
     * The nearest hit with 0 &lt; t &lt; tMax, its primitive index set. Of hits within {@link #TIE}
     * of each other the first-declared object wins, so coincident surfaces never speckle. Larger
     * scenes search a BVH ({@link ShapeSet}).
     */
    public boolean intersect(Ray ray, double tMax, Hit hit) {
        return geometry.intersect(ray, tMax, hit);
    }

    /** {@link #intersect(Ray, double, Hit)}, testing object {@code likely} first (-1: none); the same hit. */
    public boolean intersect(Ray ray, double tMax, Hit hit, int likely) {
        return geometry.intersect(ray, tMax, hit, likely);
    }

    /** Whether the scene's objects are searched through a BVH (more than {@link ShapeSet#LINEAR_MAX}), not one by one. */
    public boolean searchesBvh() {
        return geometry.usesBvh();
    }

    /** Into {@code out}, ascending: the objects rays inside the pyramid can meet; how many, or -1 (see {@link ShapeSet#candidates}). */
    public int candidates(Frustum frustum, int[] out, int[] stack) {
        return geometry.candidates(frustum, out, stack);
    }

    /** Orders a list from {@link #candidates} by distance from a point (see {@link ShapeSet#orderByDistance}). */
    public void orderByDistance(int[] ids, int count, double px, double py, double pz, double[] near) {
        geometry.orderByDistance(ids, count, px, py, pz, near);
    }

    /** {@link #intersect} for a unit-length ray that can hit only objects {@code ids[0 .. count-1]}, ordered from its origin. */
    public boolean intersectNearFirst(int[] ids, double[] near, int count, Ray ray, double tMax, Hit hit) {
        return geometry.intersectNearFirst(ids, near, count, ray, tMax, hit);
    }

    /** A box of where rays in the pyramid can hit objects {@code ids[0 .. count-1]}, or false (see {@link ShapeSet#boundsOf}). */
    public boolean boundsOf(int[] ids, int count, Frustum cameraRays, double[] box) {
        return geometry.boundsOf(ids, count, cameraRays, box);
    }

    /** {@link #occluder} for a ray that can meet only objects {@code ids[0 .. count-1]}, from {@link #candidates}. */
    public int occluderAmong(int[] ids, int count, Ray ray, double tMax) {
        return geometry.occluderAmong(ids, count, ray, tMax);
    }

    /** Whether anything lies on the ray with 0 &lt; t &lt; tMax. */
    public boolean occluded(Ray ray, double tMax) {
        return geometry.occluded(ray, tMax);
    }

    /** The index of an object that lies on the ray with 0 &lt; t &lt; tMax, or -1 if none does. */
    public int occluder(Ray ray, double tMax) {
        return geometry.occluder(ray, tMax);
    }

    /** {@link #occluder} for a shadow ray towards light {@code light}: through its light buffer, if it has one. */
    public int occluderTowards(int light, Ray ray, double tMax) {
        return geometry.occluderTowards(light, ray, tMax);
    }

    /** Whether object i lies on the ray with 0 &lt; t &lt; tMax, tested as {@link #occluded} tests it. */
    public boolean occludes(int i, Ray ray, double tMax) {
        return geometry.occludes(i, ray, tMax);
    }

    public Camera camera() {
        return camera;
    }

    public int objectCount() {
        return shapes.length;
    }

    /** How many objects are unbounded (planes), which every {@link #candidates} list holds. */
    public int unboundedCount() {
        return geometry.unboundedCount();
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

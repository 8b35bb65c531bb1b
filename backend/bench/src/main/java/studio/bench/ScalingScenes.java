package studio.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import studio.engine.camera.Camera;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Sphere;
import studio.engine.geometry.TriangleMesh;
import studio.engine.light.PointLight;
import studio.engine.material.Material;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.mesh.MeshData;
import studio.engine.mesh.MeshShapes;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;
import studio.server.scene.compiling.Colors;

/**
 * The scenes of the scaling benchmark and of the BVH micro-benchmarks, built directly through the
 * engine's API (a million spheres would make a scene file of some 100 MB). Both kinds fill the same
 * box in front of the same camera, above a ground plane, lit as the still life, so that only the
 * number of objects changes:
 * <ul>
 * <li>n spheres, centres uniform in the box, all of radius sqrt(A / (pi n)) for the box's front face
 *     area A: together they cover about 1 - 1/e of the box's front at any n (fixed seed);</li>
 * <li>a (2, 3) torus knot tessellated into about n triangles, placed as in the mesh-100k scene.</li>
 * </ul>
 */
public final class ScalingScenes {

    /** The box the objects fill: x and z in [-HALF_X, HALF_X], [-HALF_Z, HALF_Z], y in [0, HEIGHT]. */
    static final double HALF_X = 2.5, HALF_Z = 2.5, HEIGHT = 3;
    static final long SEED = 20240611L;
    public static final Camera CAMERA = new Camera(new Vec3(0, 3.5, 9), new Vec3(0, 1.4, 0), new Vec3(0, 1, 0), 40);
    static final Vec3 KNOT_POSITION = new Vec3(0, 1.6, 0), KNOT_ROTATION = new Vec3(-20, 25, 15);
    static final double KNOT_SCALE = 0.8;

    private static final Material GROUND = MaterialDefaults.of(MaterialKind.CHALK, Colors.linear("#c8c0b0"));
    private static final Material KNOT = MaterialDefaults.of(MaterialKind.PLASTIC, Colors.linear("#e0a030"));
    private static final List<PointLight> LIGHTS = List.of(
            new PointLight(new Vec3(-3, 6, 4), Rgb.WHITE, 0.85, false),
            new PointLight(new Vec3(5, 4, -2), Colors.linear("#ffd8a8"), 0.35, false));
    private static final Rgb BACKGROUND = Colors.linear("#2a2f38");
    private static final double AMBIENT = 0.07;

    private ScalingScenes() {
    }

    /** The radius of each of n spheres (see the class comment). */
    public static double sphereRadius(int n) {
        return Math.sqrt(2 * HALF_X * HEIGHT / (Math.PI * n));
    }

    /** n spheres as scene objects (chalk, colours from {@link SpheresScene#PALETTE}), the same for the same n. */
    public static List<SceneObject> spheres(int n) {
        if (n < 1) {
            throw new IllegalArgumentException("need at least one sphere: " + n);
        }
        Random random = new Random(SEED);
        Material[] materials = new Material[SpheresScene.PALETTE.length];
        for (int i = 0; i < materials.length; i++) {
            materials[i] = MaterialDefaults.of(MaterialKind.CHALK, Colors.linear(SpheresScene.PALETTE[i]));
        }
        double r = sphereRadius(n);
        List<SceneObject> objects = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            Vec3 c = new Vec3(HALF_X * (2 * random.nextDouble() - 1), HEIGHT * random.nextDouble(),
                    HALF_Z * (2 * random.nextDouble() - 1));
            objects.add(new SceneObject(new Sphere(c, r), materials[random.nextInt(materials.length)]));
        }
        return objects;
    }

    /**
     * The knot's tessellation for about n triangles: {@code {segments, sides}}, 2 x segments x sides
     * triangles, sides = sqrt(n / 40) within [3, 50] (the knot is about 20 times longer than its tube is
     * round). The fewest is 18 triangles (3 x 3).
     */
    public static int[] knotTessellation(int n) {
        int sides = (int) Math.max(3, Math.min(50, Math.round(Math.sqrt(n / 40.0))));
        int segments = (int) Math.max(3, Math.round(n / (2.0 * sides)));
        return new int[] {segments, sides};
    }

    /** The knot of about n triangles, in object space. */
    public static MeshData knot(int n) {
        int[] t = knotTessellation(n);
        return MeshShapes.torusKnot(2, 3, t[0], t[1]);
    }

    /** The knot placed in the box (this builds its BVH). */
    public static TriangleMesh placedKnot(MeshData knot) {
        return new TriangleMesh(knot, KNOT_POSITION, KNOT_SCALE, KNOT_ROTATION);
    }

    /** The objects and then the ground plane (declared last, so that it loses every tie). */
    public static List<SceneObject> withGround(List<SceneObject> objects) {
        List<SceneObject> all = new ArrayList<>(objects.size() + 1);
        all.addAll(objects);
        all.add(new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)), GROUND));
        return all;
    }

    /** The knot as a scene object. */
    public static SceneObject knotObject(TriangleMesh knot) {
        return new SceneObject(knot, KNOT);
    }

    /** The scene of these objects (builds its BVH over them if there are more than four): camera, lights and all. */
    public static Scene scene(List<SceneObject> objects) {
        return new Scene(CAMERA, objects, LIGHTS, BACKGROUND, AMBIENT);
    }
}

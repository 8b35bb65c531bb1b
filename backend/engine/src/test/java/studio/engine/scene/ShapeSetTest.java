package studio.engine.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.RayBundle;
import studio.engine.geometry.Rays;
import studio.engine.geometry.Shape;
import studio.engine.geometry.Sphere;
import studio.engine.geometry.TriangleMesh;
import studio.engine.math.Vec3;
import studio.engine.memory.CountingGate;
import studio.engine.mesh.MeshShapes;

/** The scene's BVH finds what the linear loop finds, tie rule included, whatever order it visits shapes in. */
class ShapeSetTest {

    static double uniform(Random random, double lo, double hi) {
        return lo + (hi - lo) * random.nextDouble();
    }

    static Vec3 randomUnit(Random random) {
        double z = uniform(random, -1, 1), phi = uniform(random, 0, 2 * Math.PI), r = Math.sqrt(1 - z * z);
        return new Vec3(r * Math.cos(phi), r * Math.sin(phi), z);
    }

    static Vec3 randomPoint(Random random, double extent) {
        return new Vec3(uniform(random, -extent, extent), uniform(random, -extent, extent), uniform(random, -extent, extent));
    }

    /** Random spheres, rotated boxes and a few meshes in a 20-unit cube, with two planes among them. */
    private static Shape[] randomScene(Random random, int count) {
        Shape[] shapes = new Shape[count];
        for (int i = 0; i < count; i++) {
            Vec3 c = randomPoint(random, 10);
            int kind = random.nextInt(10);
            if (i == 3) {
                shapes[i] = new Plane(new Vec3(0, -10, 0), new Vec3(0, 1, 0));
            } else if (i == count / 2) {
                shapes[i] = new Plane(new Vec3(0, 0, 12), new Vec3(0.1, 0.2, -1));
            } else if (kind < 5) {
                shapes[i] = new Sphere(c, uniform(random, 0.1, 2));
            } else if (kind < 9) {
                shapes[i] = new Box(c, new Vec3(uniform(random, 0.1, 3), uniform(random, 0.1, 3), uniform(random, 0.1, 3)),
                        new Vec3(uniform(random, -180, 180), uniform(random, -180, 180), uniform(random, -180, 180)));
            } else {
                shapes[i] = new TriangleMesh(MeshShapes.icosphere(1), c, uniform(random, 0.2, 2),
                        new Vec3(uniform(random, -180, 180), 0, 0));
            }
        }
        return shapes;
    }

    @Test
    @DisplayName("NUM-13: shadow rays through a scene's light buffers are blocked exactly when the tree says so")
    void lightBuffersAnswerOccludedExactlyAsTheTreeDoes() {
        Random random = new Random(13);
        // above, to the side, far below, and inside the scene's box (no buffer)
        List<Vec3> lights = List.of(new Vec3(2, 40, -3), new Vec3(-30, 4, 2), new Vec3(1, -60, 5), new Vec3(0.5, 0.5, 0.5));
        int rays = 0, blocked = 0;
        for (int scene = 0; scene < 6; scene++) {
            Shape[] shapes = randomScene(random, 70 + 60 * scene);
            ShapeSet plain = ShapeSets.bvh(shapes), lit = ShapeSet.of(lights, shapes);
            if (scene == 0) {
                long outside = bufferBytes(lights.subList(0, 3), shapes);
                assertTrue(outside - bufferBytes(lights.subList(0, 2), shapes) > 16 * shapes.length,
                        "the third light outside the box has a buffer: " + outside + " bytes for three");
                long all = bufferBytes(lights, shapes);
                assertTrue(Math.abs(all - outside) < outside / 30, "the light inside the box has none: " + all + " bytes for four");
            }
            Hit hit = new Hit();
            for (int k = 0; k < 3000; k++) {
                int light = k % lights.size();
                Vec3 target = lights.get(light), from;
                Ray ray;
                double tMax;
                if (k % 2 == 0) { // from a surface, as a shadow ray leaves one
                    Vec3 o = randomPoint(random, 14), d = randomUnit(random);
                    if (!plain.intersect(new Ray(o.x(), o.y(), o.z(), d.x(), d.y(), d.z()), Double.POSITIVE_INFINITY, hit)) {
                        continue;
                    }
                    ray = Rays.spawnTowards(hit, target.x(), target.y(), target.z());
                    from = new Vec3(ray.ox, ray.oy, ray.oz);
                } else {
                    from = randomPoint(random, 12);
                    Vec3 d = target.minus(from).normalized();
                    ray = new Ray(from.x(), from.y(), from.z(), d.x(), d.y(), d.z());
                }
                tMax = target.minus(from).length() * (1 - 1e-9);
                if (k % 5 == 4) { // any other ray: the buffer leaves most to the tree
                    Vec3 d = randomUnit(random);
                    ray = new Ray(from.x(), from.y(), from.z(), d.x(), d.y(), d.z());
                    tMax = uniform(random, 0, 30);
                }
                boolean expected = plain.occluded(ray, tMax);
                assertEquals(expected, lit.occluded(ray, tMax), ray::toString);
                blocked += expected ? 1 : 0;
                rays++;
            }
        }
        assertTrue(blocked > rays / 10 && blocked < rays * 9 / 10, blocked + " of " + rays + " blocked");
        long few = bufferBytes(lights, randomScene(random, ShapeSet.LIGHT_BUFFER_MIN));
        assertTrue(few < 512, "fewer bounded shapes than the minimum (two of them are planes): no buffers, " + few + " bytes");
    }

    /**
     * What a set made with these lights keeps beyond the same set made without lights: the memory
     * of its light buffers (each keeps lists over the set's shapes).
     */
    private static long bufferBytes(List<Vec3> lights, Shape[] shapes) {
        ShapeSet.of(lights, shapes); // the classes loaded before measuring
        return CountingGate.allocatedBy(() -> ShapeSet.of(lights, shapes))
                - CountingGate.allocatedBy(() -> ShapeSet.of(List.of(), shapes));
    }

    @Test
    void bvhFindsTheSameHitAndObjectAsTheLinearLoopOnRandomScenes() {
        Random random = new Random(12);
        int hits = 0;
        for (int scene = 0; scene < 10; scene++) {
            Shape[] shapes = randomScene(random, 20 + 20 * scene);
            ShapeSet linear = ShapeSets.linear(shapes), bvh = ShapeSets.bvh(shapes);
            Hit a = new Hit(), b = new Hit(), c = new Hit();
            for (int i = 0; i < 1000; i++) {
                Ray ray = randomRay(random, shapes);
                double tMax = random.nextInt(4) == 0 ? uniform(random, 0, 40) : Double.POSITIVE_INFINITY;

                boolean expected = linear.intersect(ray, tMax, a);
                boolean actual = bvh.intersect(ray, tMax, b);

                assertEquals(expected, actual, ray.toString());
                assertEquals(expected, bvh.occluded(ray, tMax), "any-hit " + ray);
                assertEquals(expected, linear.occluded(ray, tMax), "linear any-hit " + ray);
                if (expected) {
                    hits++;
                    assertEquals(a.primitive, b.primitive, ray.toString());
                    assertEquals(a.t, b.t, 0.0);
                    assertEquals(a.px, b.px, 0.0);
                    assertEquals(a.nx, b.nx, 0.0);
                }
            }
        }
        assertTrue(hits > 6000, "rays that hit: " + hits);
    }

    @Test
    void aSetOfSomeShapesFindsWhatTheLinearLoopOverThemFindsAndNamesThemByTheirSceneIndex() {
        Random random = new Random(47);
        int hits = 0;
        for (int scene = 0; scene < 4; scene++) {
            Shape[] shapes = randomScene(random, 30 + 30 * scene);
            boolean[] members = new boolean[shapes.length];
            List<Shape> chosen = new ArrayList<>();
            List<Integer> index = new ArrayList<>();
            for (int i = 0; i < shapes.length; i++) {
                members[i] = random.nextInt(3) > 0;
                if (members[i]) {
                    chosen.add(shapes[i]);
                    index.add(i);
                }
            }
            ShapeSet some = ShapeSet.of(List.of(), shapes, members, false);
            ShapeSet reference = ShapeSets.linear(chosen.toArray(Shape[]::new));
            assertEquals(chosen.size(), some.size());
            Hit a = new Hit(), b = new Hit();
            for (int k = 0; k < 1000; k++) {
                Ray ray = randomRay(random, shapes);
                double tMax = random.nextInt(4) == 0 ? uniform(random, 0, 40) : Double.POSITIVE_INFINITY;
                boolean expected = reference.intersect(ray, tMax, a);
                assertEquals(expected, some.intersect(ray, tMax, b), ray.toString());
                assertEquals(expected, some.occluded(ray, tMax), "any-hit " + ray);
                // whatever blocked the ray object last, a member or not, in range or not: the same answer
                ray.blocker = random.nextInt(shapes.length + 4) - 2;
                assertEquals(expected, some.occluded(ray, tMax), "any-hit after blocker " + ray.blocker + ", " + ray);
                if (expected) {
                    hits++;
                    assertEquals((int) index.get(a.primitive), b.primitive, "named by its index in the scene");
                    assertEquals(a.t, b.t, 0.0);
                }
            }
        }
        assertTrue(hits > 2000, "rays that hit: " + hits);
    }

    /** A ray from inside a random shape (a third of the time), or from anywhere in or around the scene. */
    private static Ray randomRay(Random random, Shape[] shapes) {
        Vec3 o;
        if (random.nextInt(3) == 0) {
            Shape s = shapes[random.nextInt(shapes.length)];
            o = s instanceof Sphere sphere ? sphere.center() : s instanceof Box box ? box.center()
                    : s instanceof TriangleMesh mesh ? mesh.position() : randomPoint(random, 10);
        } else {
            o = randomPoint(random, 15);
        }
        return new Ray(o, randomUnit(random).times(uniform(random, 0.5, 2)));
    }

    @Test
    @DisplayName("NUM-12 with a BVH and through a pixel's ray bundle: the first-declared of coincident surfaces wins, in either declaration order")
    void coincidentSurfacesNum12FirstDeclaredWinsThroughTheBvhInEitherOrder() {
        Plane plane = new Plane(Vec3.ZERO, new Vec3(0, 1, 0));
        Box box = new Box(new Vec3(0, -0.5, 0), new Vec3(2, 1, 2));
        Sphere sphere = new Sphere(new Vec3(3, 0, 0), 0.7);
        Sphere sameSphere = new Sphere(new Vec3(3, 0, 0), 0.7);
        Box sameBox = new Box(new Vec3(0, -0.5, 0), new Vec3(2, 1, 2));
        Random random = new Random(13);
        List<Shape> fillers = new ArrayList<>();
        for (int i = 0; i < 12; i++) {
            fillers.add(new Sphere(new Vec3(uniform(random, -8, 8), uniform(random, 4, 8), uniform(random, -8, -4)), 0.5));
        }
        Camera camera = new Camera(new Vec3(1.3, 1.7, 2.9), new Vec3(1, 0, 0), new Vec3(0, 1, 0), 60);
        Hit hit = new Hit(), reference = new Hit(), bundled = new Hit();
        RayBundle bundle = new RayBundle();
        Vec3 eye = camera.position();
        for (int order = 0; order < 8; order++) {
            // Coincident pairs (plane, box, sameBox) and (sphere, sameSphere) at shuffled positions among fillers.
            List<Shape> list = new ArrayList<>(fillers);
            List<Shape> tied = new ArrayList<>(List.of(plane, box, sameBox, sphere, sameSphere));
            Collections.shuffle(tied, random);
            for (Shape s : tied) {
                list.add(random.nextInt(list.size() + 1), s);
            }
            Shape[] shapes = list.toArray(Shape[]::new);
            ShapeSet set = ShapeSets.bvh(shapes); // with its bundles, as ShapeSet.of makes it of more than LINEAR_MAX shapes
            ShapeSet linear = ShapeSets.linear(shapes);
            int flat = Math.min(list.indexOf(plane), Math.min(list.indexOf(box), list.indexOf(sameBox)));
            int round = Math.min(list.indexOf(sphere), list.indexOf(sameSphere));
            int onPairs = 0;
            for (int y = 0; y < 128; y++) {
                for (int x = 0; x < 128; x++) {
                    Ray ray = camera.ray(2 * (x + 0.5) / 128 - 1, 1 - 2 * (y + 0.5) / 128, 1.0);
                    boolean found = set.intersect(ray, Double.POSITIVE_INFINITY, hit);
                    assertEquals(linear.intersect(ray, Double.POSITIVE_INFINITY, reference), found);
                    camera.frustum(2.0 * x / 128 - 1, 2.0 * (x + 1) / 128 - 1, 1 - 2.0 * (y + 1) / 128,
                            1 - 2.0 * y / 128, 1.0, bundle.aim(eye.x(), eye.y(), eye.z()));
                    ray.bundle = bundle;
                    assertEquals(found, set.intersect(ray, Double.POSITIVE_INFINITY, bundled), "through the pixel's bundle");
                    assertTrue(bundle.count >= 0, "a pixel's list fits");
                    if (!found) {
                        continue;
                    }
                    assertEquals(reference.primitive, hit.primitive, "same winner as the linear loop");
                    assertEquals(reference.primitive, bundled.primitive, "the bundle's winner is the linear loop's");
                    assertEquals(reference.t, hit.t, 0.0);
                    assertEquals(reference.t, bundled.t, 0.0);
                    Shape winner = shapes[hit.primitive];
                    if (winner == plane || winner == box || winner == sameBox) {
                        if (Math.abs(hit.px) < 0.99 && Math.abs(hit.pz) < 0.99) {
                            assertEquals(flat, hit.primitive, "the first-declared flat surface wins");
                            onPairs++;
                        }
                    } else if (winner == sphere || winner == sameSphere) {
                        assertEquals(round, hit.primitive, "the first-declared of the two spheres wins");
                        onPairs++;
                    }
                }
            }
            assertTrue(onPairs > 2000, "pixels on coincident surfaces: " + onPairs);
        }
    }

    @Test
    void aClearlyNearerLaterShapeStillWinsThroughTheBvh() {
        List<Shape> shapes = new ArrayList<>();
        shapes.add(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)));
        for (int i = 0; i < 10; i++) {
            shapes.add(new Sphere(new Vec3(10 + i, 5, 0), 0.5));
        }
        shapes.add(new Box(new Vec3(0, -0.5 + 1e-6, 0), new Vec3(2, 1, 2)));
        ShapeSet set = ShapeSet.of(shapes.toArray(Shape[]::new));
        Hit hit = new Hit();

        assertTrue(set.intersect(new Ray(0.1, 1, 0.2, 0, -1, 0), Double.POSITIVE_INFINITY, hit));

        assertEquals(11, hit.primitive);
        assertEquals(1 - 1e-6, hit.t, 1e-15);
    }

    /**
     * Sets of a few shapes, and of planes alone, find what the tree finds and what lies on the ray.
     * Which way a set of a given size takes is a speed choice, measured by {@code ShapeSetTiming}.
     */
    @Test
    void smallSetsAndSetsOfPlanesAloneFindTheNearestHit() {
        Shape[] few = new Shape[ShapeSet.LINEAR_MAX];
        for (int i = 0; i < few.length; i++) {
            few[i] = new Sphere(new Vec3(i, 0, 0), 0.25);
        }
        Shape[] planes = new Shape[20];
        for (int i = 0; i < planes.length; i++) {
            planes[i] = new Plane(new Vec3(0, i, 0), new Vec3(0, 1, 0));
        }

        Hit hit = new Hit(), reference = new Hit();
        Ray along = new Ray(-5, 0.1, 0, 1, 0, 0);
        assertTrue(ShapeSet.of(few).intersect(along, Double.POSITIVE_INFINITY, hit));
        assertTrue(ShapeSets.bvh(few).intersect(along, Double.POSITIVE_INFINITY, reference));
        assertEquals(0, hit.primitive);
        assertEquals(reference.t, hit.t, 0.0);
        assertTrue(ShapeSet.of(few).occluded(along, Double.POSITIVE_INFINITY));
        assertFalse(ShapeSet.of(few).occluded(new Ray(-5, 1, 0, 1, 0, 0), Double.POSITIVE_INFINITY));
        assertTrue(ShapeSet.of(planes).intersect(new Ray(0, 30, 0, 0, -1, 0), Double.POSITIVE_INFINITY, hit));
        assertEquals(19, hit.primitive);
        assertFalse(ShapeSet.of(planes).occluded(new Ray(0, 30, 0, 0, 1, 0), Double.POSITIVE_INFINITY));
    }
}

package studio.engine.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static studio.engine.scene.ShapeSetTest.randomPoint;
import static studio.engine.scene.ShapeSetTest.randomUnit;
import static studio.engine.scene.ShapeSetTest.uniform;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.accel.Aabb;
import studio.engine.geometry.Box;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Rays;
import studio.engine.geometry.Shape;
import studio.engine.geometry.Sphere;
import studio.engine.geometry.TriangleMesh;
import studio.engine.math.Vec3;
import studio.engine.mesh.MeshShapes;

/**
 * Rays that carry the shape they start within ({@link Ray#within}): the set tests it first and may
 * skip its tree, and finds the linear loop's hit to the bit, neighbours near the shape included.
 */
class ShapeSetWithinTest {

    /**
     * Shapes far apart, with here and there a neighbour that touches another's box or reaches
     * into it. Rays that enter a shape (spawned from its surface as the integrator
     * spawns a refracted ray) or start deep inside it, carrying that shape as the one they start within:
     * where it stands apart the tree is not searched, and the hit is the full search's to the bit. The
     * scenes hold both kinds, shapes standing apart and shapes with a neighbour near (worked out here
     * from the shapes' boxes, as {@code ShapeSet} does).
     */
    @Test
    void aRayInsideAShapeThatStandsApartFindsTheFullSearchsHitWithoutTheTree() {
        Random random = new Random(31);
        int apart = 0, near = 0, inside = 0;
        for (int scene = 0; scene < 6; scene++) {
            List<Shape> list = new ArrayList<>();
            list.add(new Plane(new Vec3(0, -60, 0), new Vec3(0, 1, 0)));
            for (int i = 0; i < 40; i++) {
                Vec3 c = randomPoint(random, 50);
                Shape shape = switch (random.nextInt(3)) {
                    case 0 -> new Sphere(c, uniform(random, 0.5, 3));
                    case 1 -> new Box(c, new Vec3(uniform(random, 0.5, 4), uniform(random, 0.5, 4), uniform(random, 0.5, 4)),
                            new Vec3(uniform(random, -180, 180), uniform(random, -180, 180), 0));
                    default -> new TriangleMesh(MeshShapes.icosphere(1), c, uniform(random, 0.5, 2), Vec3.ZERO);
                };
                list.add(shape);
                if (i % 5 == 0) {
                    // a neighbour whose box touches this one's, or which reaches into it
                    double reach = shape.bounds().maxX() + (random.nextBoolean() ? 0.5 : -0.2);
                    list.add(new Sphere(new Vec3(reach, c.y(), c.z()), 0.5));
                }
            }
            Shape[] shapes = list.toArray(Shape[]::new);
            ShapeSet set = ShapeSets.bvh(shapes), linear = ShapeSets.linear(shapes);
            Hit a = new Hit(), b = new Hit(), c = new Hit(), entry = new Hit();
            for (int i = 1; i < shapes.length; i++) {
                boolean standsApart = standsApart(shapes, i);
                apart += standsApart ? 1 : 0;
                near += standsApart ? 0 : 1;
                for (int k = 0; k < 40; k++) {
                    Vec3 target = shapes[i] instanceof Sphere sp ? sp.center() : shapes[i] instanceof Box bx ? bx.center()
                            : ((TriangleMesh) shapes[i]).position();
                    Vec3 from = target.plus(randomUnit(random).times(40));
                    Ray toward = new Ray(from, target.minus(from).plus(randomUnit(random).times(0.3)));
                    if (!linear.intersect(toward, Double.POSITIVE_INFINITY, entry) || entry.primitive != i) {
                        continue;
                    }
                    Ray ray = k % 4 == 0 ? new Ray(target, randomUnit(random).times(uniform(random, 0.1, 10)))
                            : Rays.spawn(entry, toward.dx, toward.dy, toward.dz);
                    if (k % 4 != 0) {
                        assertEquals(i, ray.within, "a ray spawned into a shape starts within it");
                    }
                    inside++;
                    double tMax = k % 3 == 0 ? uniform(random, 0, 5) : Double.POSITIVE_INFINITY;
                    boolean expected = linear.intersect(ray, tMax, a);
                    ray.within = -1;
                    assertEquals(expected, set.intersect(ray, tMax, b), ray.toString());
                    ray.within = i;
                    assertEquals(expected, set.intersect(ray, tMax, c), "within " + i + ", " + ray);
                    if (expected) {
                        assertEquals(a.primitive, c.primitive, ray.toString());
                        assertEquals(b.primitive, c.primitive, ray.toString());
                        assertEquals(Double.doubleToRawLongBits(b.t), Double.doubleToRawLongBits(c.t));
                        assertEquals(Double.doubleToRawLongBits(b.px), Double.doubleToRawLongBits(c.px));
                        assertEquals(Double.doubleToRawLongBits(b.py), Double.doubleToRawLongBits(c.py));
                        assertEquals(Double.doubleToRawLongBits(b.pz), Double.doubleToRawLongBits(c.pz));
                        assertEquals(Double.doubleToRawLongBits(b.nx), Double.doubleToRawLongBits(c.nx));
                        assertEquals(Double.doubleToRawLongBits(b.gz), Double.doubleToRawLongBits(c.gz));
                    }
                }
            }
        }
        assertTrue(apart > 100 && near > 50 && inside > 5000, "apart " + apart + ", near " + near + ", rays " + inside);
    }

    /**
     * Whether no other bounded shape's box comes within twice the set's margin ({@link ShapeSet#APART_MARGIN}
     * of the largest coordinate of the bounded shapes' boxes) of shape i's box.
     */
    private static boolean standsApart(Shape[] shapes, int i) {
        double largest = 0;
        for (Shape shape : shapes) {
            Aabb b = shape.bounds();
            if (b.isBounded()) {
                for (double v : new double[] {b.minX(), b.minY(), b.minZ(), b.maxX(), b.maxY(), b.maxZ()}) {
                    largest = Math.max(largest, Math.abs(v));
                }
            }
        }
        double m = 2 * Math.max(ShapeSet.APART_MARGIN * largest, Double.MIN_NORMAL);
        Aabb a = shapes[i].bounds();
        for (int j = 0; j < shapes.length; j++) {
            Aabb b = shapes[j].bounds();
            if (j != i && b.isBounded() && b.minX() <= a.maxX() + m && b.minY() <= a.maxY() + m && b.minZ() <= a.maxZ() + m
                    && b.maxX() >= a.minX() - m && b.maxY() >= a.minY() - m && b.maxZ() >= a.minZ() - m) {
                return false;
            }
        }
        return true;
    }

    /**
     * A ray that carries a shape as the one it starts within, where a neighbour comes within twice
     * the margin of that shape's box, still finds the neighbour when the neighbour is hit first on
     * the part of the ray inside the shape's widened box (touching boxes, a gap of a millionth);
     * a neighbour a thousandth away, far more than the margin, is found as well where it is hit.
     */
    @Test
    void aNeighbourWithinTwiceTheMarginIsFoundFromInsideTheShape() {
        // the largest coordinate is about 100, so the margin is about 1e-5
        Sphere far = new Sphere(new Vec3(100, 0, 0), 1);
        Sphere a = new Sphere(new Vec3(0, 0, 0), 1);
        Box touching = new Box(new Vec3(0, 2, 0), new Vec3(2, 2, 2)); // its face on the sphere's top
        Sphere b = new Sphere(new Vec3(0, 0, 20), 1);
        Sphere closeToB = new Sphere(new Vec3(0, 0, 22 + 1e-6), 1);
        Sphere c = new Sphere(new Vec3(0, 0, -20), 1);
        Sphere clearOfC = new Sphere(new Vec3(0, 0, -22 - 1e-3), 1);
        Shape[] shapes = {far, a, touching, b, closeToB, c, clearOfC};
        ShapeSet set = ShapeSets.bvh(shapes), linear = ShapeSets.linear(shapes);
        // within, origin, direction, the shape hit first
        double[][] cases = {
                {0, 100, 0, 0, 1, 0.2, 0, 0},
                {1, 0.5, 1 + 5e-6, 0.5, 0, -1, 0, 2}, // in the box just above the sphere's top: the box's face first
                {2, 0, 1 - 5e-6, 0, 1, 1e-4, 0, 1}, // in the sphere just under the box, along it: the sphere first
                {3, 0, 0, 21 + 5e-6, 0, 0, -1, 4}, // in b's near neighbour, towards b: the neighbour first
                {4, 0, 0, 21 - 5e-6, 0, 0, 1, 3}, // in b, towards its near neighbour: b first
                {5, 0, 0, -20.5, 0, 0, -1, 5}, // in c, towards the sphere clear of it: c first
                {6, 0, 0, -21.5, 0, 0, 1, 6}, // in the sphere clear of c, towards c: itself first
                {5, 0, 0, -21 - 5e-4, 0, 0, -1, 6}, // between c and the sphere clear of it: that sphere
        };
        Hit expected = new Hit(), found = new Hit();
        for (double[] k : cases) {
            Ray ray = new Ray(k[1], k[2], k[3], k[4], k[5], k[6]);
            assertTrue(linear.intersect(ray, Double.POSITIVE_INFINITY, expected));
            assertEquals((int) k[7], expected.primitive, ray.toString());
            ray.within = (int) k[0];
            assertTrue(set.intersect(ray, Double.POSITIVE_INFINITY, found));
            assertEquals((int) k[7], found.primitive, "within " + ray.within + ", " + ray);
            assertEquals(Double.doubleToRawLongBits(expected.t), Double.doubleToRawLongBits(found.t));
        }
    }
}

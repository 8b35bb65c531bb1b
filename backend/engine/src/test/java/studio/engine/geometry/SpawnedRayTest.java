package studio.engine.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static studio.engine.geometry.GeometryAssertions.randomUnit;
import static studio.engine.geometry.GeometryAssertions.uniform;

import java.util.Random;
import java.util.function.DoubleUnaryOperator;
import java.util.stream.Stream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import studio.engine.math.Rotation;
import studio.engine.math.Vec3;

/**
 * Property: a ray spawned from a hit with {@link Rays#spawn}, leaving on either side (reflection away from the
 * surface, refraction into it), never hits the same surface again near t = 0. Closed convex shapes are hit
 * again only across their interior, a fair fraction of a chord away; planes are never hit again.
 */
class SpawnedRayTest {

    private static final int CASES = 10_000;

    static Stream<Arguments> scalesAndTranslations() {
        return Stream.of(Arguments.of(1e-4, 0.0), Arguments.of(1.0, 0.0), Arguments.of(1e4, 0.0),
                Arguments.of(1.0, 1e12), Arguments.of(1e4, 1e12));
    }

    @ParameterizedTest(name = "scale {0}, translated by {1}")
    @MethodSource("scalesAndTranslations")
    void rayFromSphereHitNeverRehitsTheSphereNearItsOrigin(double scale, double translation) {
        Random random = new Random(1 + Double.hashCode(scale) * 31L + Double.hashCode(translation));
        Failures failures = new Failures();
        Hit hit = new Hit(), again = new Hit();
        for (int i = 0; i < CASES; i++) {
            Vec3 c = translated(translation).plus(randomUnit(random).times(scale * uniform(random, 0, 3)));
            double r = scale * uniform(random, 0.5, 2);
            Sphere sphere = new Sphere(c, r);
            Vec3 n = randomUnit(random);
            Vec3 p = c.plus(n.times(r));
            boolean fromInside = random.nextBoolean();
            Ray primary;
            if (fromInside) {
                Vec3 o = c.plus(randomUnit(random).times(r * uniform(random, 0, 0.5)));
                primary = new Ray(o, p.minus(o));
            } else {
                Vec3 d = incoming(random, n);
                primary = new Ray(p.minus(d.times(r * uniform(random, 0.5, 5))), d);
            }
            if (!sphere.intersect(primary, Double.POSITIVE_INFINITY, hit)) {
                failures.add("primary ray missed " + sphere + ": " + primary);
                continue;
            }
            // A chord at angle theta to the normal is 2 r cos(theta) long; accept anything beyond 5 % of it.
            checkBothSides(sphere, primary, hit, again, random, cos -> 0.1 * r * cos, failures);
        }
        failures.assertNone();
    }

    @ParameterizedTest(name = "scale {0}, translated by {1}")
    @MethodSource("scalesAndTranslations")
    void rayFromBoxHitNeverRehitsTheBoxNearItsOrigin(double scale, double translation) {
        Random random = new Random(2 + Double.hashCode(scale) * 31L + Double.hashCode(translation));
        Failures failures = new Failures();
        Hit hit = new Hit(), again = new Hit();
        for (int i = 0; i < CASES; i++) {
            Vec3 c = translated(translation).plus(randomUnit(random).times(scale * uniform(random, 0, 3)));
            Vec3 size = new Vec3(uniform(random, 0.5, 2), uniform(random, 0.5, 2), uniform(random, 0.5, 2))
                    .times(scale);
            Vec3 degrees = random.nextInt(4) == 0 ? Vec3.ZERO
                    : new Vec3(uniform(random, -180, 180), uniform(random, -180, 180), uniform(random, -180, 180));
            Box box = new Box(c, size, degrees);
            Rotation rotation = Rotation.fromEulerDegrees(degrees);
            int axis = random.nextInt(3);
            double sign = random.nextBoolean() ? 1 : -1;
            // a point on one face, at least 10 % of the face away from its edges
            double[] local = {uniform(random, -0.8, 0.8) * size.x() / 2, uniform(random, -0.8, 0.8) * size.y() / 2,
                    uniform(random, -0.8, 0.8) * size.z() / 2};
            local[axis] = sign * size.get(axis) / 2;
            double[] localNormal = new double[3];
            localNormal[axis] = sign;
            Vec3 p = c.plus(rotation.apply(new Vec3(local[0], local[1], local[2])));
            Vec3 n = rotation.apply(new Vec3(localNormal[0], localNormal[1], localNormal[2]));
            boolean fromInside = random.nextBoolean();
            Ray primary;
            if (fromInside) {
                Vec3 o = c.plus(rotation.apply(new Vec3(uniform(random, -0.5, 0.5) * size.x() / 2,
                        uniform(random, -0.5, 0.5) * size.y() / 2, uniform(random, -0.5, 0.5) * size.z() / 2)));
                primary = new Ray(o, p.minus(o));
            } else {
                Vec3 d = incoming(random, n);
                primary = new Ray(p.minus(d.times(scale * uniform(random, 0.5, 5))), d);
            }
            if (!box.intersect(primary, Double.POSITIVE_INFINITY, hit)) {
                failures.add("primary ray missed " + box + ": " + primary);
                continue;
            }
            // From a face point 10 % of the face inside its edges, a ray into the box travels at least
            // 0.2 * the smallest half-size before it reaches another face; accept anything beyond half of that.
            double minHalf = Math.min(size.x(), Math.min(size.y(), size.z())) / 2;
            checkBothSides(box, primary, hit, again, random, cos -> 0.1 * minHalf, failures);
        }
        failures.assertNone();
    }

    @ParameterizedTest(name = "scale {0}, translated by {1}")
    @MethodSource("scalesAndTranslations")
    void rayFromTiltedPlaneHitNeverRehitsThePlane(double scale, double translation) {
        Random random = new Random(3 + Double.hashCode(scale) * 31L + Double.hashCode(translation));
        Failures failures = new Failures();
        Hit hit = new Hit(), again = new Hit();
        for (int i = 0; i < CASES; i++) {
            Vec3 point = translated(translation).plus(randomUnit(random).times(scale * uniform(random, 0, 3)));
            Plane plane = new Plane(point, randomUnit(random));
            Vec3 n = plane.normal();
            Vec3 tangent = randomUnit(random).cross(n);
            Vec3 p = point.plus(tangent.times(scale * uniform(random, 0, 3)));
            Vec3 d = incoming(random, n);
            if (random.nextBoolean()) {
                d = d.negated(); // from behind
            }
            Ray primary = new Ray(p.minus(d.times(scale * uniform(random, 0.5, 5))), d);
            if (!plane.intersect(primary, Double.POSITIVE_INFINITY, hit)) {
                failures.add("primary ray missed " + plane + ": " + primary);
                continue;
            }
            Vec3 r = reflected(primary, hit);
            for (Ray spawned : new Ray[] {Rays.spawn(hit, r.x(), r.y(), r.z()), spawnThrough(hit, primary, random)}) {
                if (plane.intersect(spawned, Double.POSITIVE_INFINITY, again)
                        || plane.occluded(spawned, Double.POSITIVE_INFINITY)) {
                    failures.add("re-hit " + plane + " at t=" + again.t + " from " + spawned
                            + " (primary " + primary + ")");
                }
            }
        }
        failures.assertNone();
    }

    /**
     * A smooth triangle whose vertex normals lean up to 80 degrees from its face: a ray spawned from a hit
     * on it, in any direction not grazing the face, never hits it again (it is flat), however far the
     * interpolated normal leans. The origin is moved off along the face's own normal; moved along the
     * interpolated one it could land on the wrong side of the face (where the two normals disagree about
     * the new ray's side) or not clear the point's rounding error across the face.
     */
    @ParameterizedTest(name = "scale {0}, translated by {1}")
    @MethodSource("scalesAndTranslations")
    void rayFromSmoothTriangleNeverRehitsIt(double scale, double translation) {
        Random random = new Random(4 + Double.hashCode(scale) * 31L + Double.hashCode(translation));
        Failures failures = new Failures();
        Hit hit = new Hit(), again = new Hit();
        for (int i = 0; i < CASES / 10; i++) {
            Vec3 centre = translated(translation).plus(randomUnit(random).times(scale * uniform(random, 0, 3)));
            Vec3 a = centre.plus(randomUnit(random).times(scale)), b = centre.plus(randomUnit(random).times(scale));
            Vec3 c = centre.plus(randomUnit(random).times(scale));
            Vec3 g = b.minus(a).cross(c.minus(a));
            if (g.length() < 0.2 * scale * scale) {
                continue; // a sliver: its own rounding is another test's matter
            }
            g = g.normalized();
            double[] normals = new double[9];
            for (int v = 0; v < 3; v++) {
                Vec3 lean = randomUnit(random).cross(g).normalized();
                double angle = Math.toRadians(uniform(random, 0, 80));
                Vec3 n = g.times(Math.cos(angle)).plus(lean.times(Math.sin(angle)));
                normals[3 * v] = n.x();
                normals[3 * v + 1] = n.y();
                normals[3 * v + 2] = n.z();
            }
            TriangleMesh mesh = new TriangleMesh(new studio.engine.mesh.MeshData(new double[] {a.x(), a.y(), a.z(),
                    b.x(), b.y(), b.z(), c.x(), c.y(), c.z()}, new int[] {0, 1, 2}, normals));
            double u = uniform(random, 0.1, 0.8), w = uniform(random, 0.1, 0.9 - u);
            Vec3 p = a.plus(b.minus(a).times(u)).plus(c.minus(a).times(w));
            Vec3 d = incoming(random, g);
            if (random.nextBoolean()) {
                d = d.negated();
            }
            Ray primary = new Ray(p.minus(d.times(scale * uniform(random, 0.5, 5))), d);
            if (!mesh.intersect(primary, Double.POSITIVE_INFINITY, hit)) {
                continue; // the primary ray slipped off an edge: nothing to spawn from
            }
            for (int k = 0; k < 8; k++) {
                Vec3 out = randomUnit(random);
                if (Math.abs(out.dot(g)) < 0.05) {
                    continue;
                }
                Ray spawned = Rays.spawn(hit, out.x(), out.y(), out.z());
                if (mesh.intersect(spawned, Double.POSITIVE_INFINITY, again) || mesh.occluded(spawned, Double.POSITIVE_INFINITY)) {
                    failures.add("re-hit the smooth triangle at t=" + again.t + " from " + spawned + " (primary " + primary + ")");
                }
            }
        }
        failures.assertNone();
    }

    /**
     * Spawns the mirror reflection and a random direction through the surface from the hit and checks them
     * against the shape: a ray leaving the closed shape never hits it; a ray going into it hits the far wall,
     * no closer than {@code minDistance} of the cosine between the ray and the inward normal.
     */
    private static void checkBothSides(Shape shape, Ray primary, Hit hit, Hit again, Random random,
                                       DoubleUnaryOperator minDistance, Failures failures) {
        Vec3 n = hit.normal();
        Vec3 r = reflected(primary, hit);
        Ray[] spawned = {Rays.spawn(hit, r.x(), r.y(), r.z()), spawnThrough(hit, primary, random)};
        for (Ray ray : spawned) {
            Vec3 w = ray.direction().normalized();
            double cos = w.dot(n);
            boolean hits = shape.intersect(ray, Double.POSITIVE_INFINITY, again);
            if (hits != shape.occluded(ray, Double.POSITIVE_INFINITY)) {
                failures.add("intersect and occluded disagree for " + ray + " on " + shape);
            } else if (cos > 0 && hits) {
                failures.add("ray leaving " + shape + " hit it again at t=" + again.t + ": " + ray
                        + " (primary " + primary + ")");
            } else if (cos < 0 && !hits) {
                failures.add("ray into closed " + shape + " found no far wall: " + ray
                        + " (primary " + primary + ")");
            } else if (cos < 0 && again.t * ray.direction().length() < minDistance.applyAsDouble(-cos)) {
                failures.add("ray into " + shape + " re-hit at t=" + again.t + " (cos " + cos + "): " + ray
                        + " (primary " + primary + ")");
            }
        }
    }

    /** The primary ray's mirror direction about the hit normal: it stays on the side the ray came from. */
    private static Vec3 reflected(Ray primary, Hit hit) {
        Vec3 d = primary.direction().normalized(), n = hit.normal();
        return d.minus(n.times(2 * d.dot(n)));
    }

    /** A ray from the hit in a random direction through the surface (refraction-like), not grazing it. */
    private static Ray spawnThrough(Hit hit, Ray primary, Random random) {
        Vec3 n = hit.normal();
        double side = Math.signum(primary.direction().dot(n)); // the side the ray goes on to
        Vec3 w = randomUnit(random);
        double cos = w.dot(n) * side;
        if (cos < 0.05) {
            w = w.plus(n.times(side * (0.05 - cos + uniform(random, 0, 1)))).normalized();
        }
        return Rays.spawn(hit, w.x(), w.y(), w.z());
    }

    /** A random unit direction going against n, not grazing the surface. */
    private static Vec3 incoming(Random random, Vec3 n) {
        Vec3 d = randomUnit(random);
        double cos = d.dot(n);
        if (cos > -0.05) {
            d = d.minus(n.times(cos + 0.05 + uniform(random, 0, 1))).normalized();
        }
        return d;
    }

    private static Vec3 translated(double t) {
        return new Vec3(t, t, t);
    }

    /** Collects failures so a broken property reports how often it fails, not just the first case. */
    private static final class Failures {
        private int count;
        private String first;

        void add(String message) {
            if (count++ == 0) {
                first = message;
            }
        }

        void assertNone() {
            assertEquals(0, count, () -> count + " of the cases failed; first: " + first);
        }
    }
}

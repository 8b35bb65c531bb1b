package studio.engine.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static studio.engine.geometry.GeometryAssertions.assertVec;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.light.PointLight;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.render.RenderResult;
import studio.engine.render.RenderSettings;
import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.engine.sampler.RegularSampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/** The intersection-level cases of docs/robustness.md (NUM-01, -03, -04, -07, -10) with their exact inputs. */
class StabilityIntersectionTest {

    /** NUM-01 / NUM-03: a ray from the origin passing at perpendicular distance p from the centre (0,0,-dist). */
    private static Ray rayPassingAt(double p, double dist) {
        double theta = Math.asin(p / dist);
        return new Ray(0, 0, 0, Math.sin(theta), 0, -Math.cos(theta));
    }

    @Test
    void farSphereNum01PointRaysHitAtTheExactDistanceOrMiss() {
        Sphere sphere = new Sphere(new Vec3(0, 0, -1e7), 1);
        double[] ps = {0, 0.5, 0.99, 0.999, 0.9995};
        double[] expected = {9999999.0, 9999999.133974584, 9999999.858932590, 9999999.955289772, 9999999.968381127};
        for (int i = 0; i < ps.length; i++) {
            Hit hit = new Hit();

            assertTrue(sphere.intersect(rayPassingAt(ps[i], 1e7), Double.POSITIVE_INFINITY, hit), "p=" + ps[i]);

            assertEquals(expected[i], hit.t, 1e-6, "p=" + ps[i]);
            assertTrue(hit.normal().isFinite() && hit.normal().z() > 0, "front-facing normal at p=" + ps[i]);
        }
        assertFalse(sphere.intersect(rayPassingAt(1.0005, 1e7), Double.POSITIVE_INFINITY, new Hit()));
        assertFalse(sphere.intersect(rayPassingAt(1.001, 1e7), Double.POSITIVE_INFINITY, new Hit()));
    }

    @Test
    void farSphereNum01SweepOf2001RaysHasNoMisclassifiedRay() {
        assertEquals(0, misclassified(1e7, 0.9, 1.1, 2001));
    }

    @Test
    void grazingSphereNum03SweepOf4001RaysAtTheSilhouetteHasNoMisclassifiedRay() {
        assertEquals(0, misclassified(1e5, 1 - 2e-5, 1 + 2e-5, 4001));
    }

    /** Counts rays (|p - 1| > 1e-9) whose hit or miss is wrong, or whose hit is NaN or back-facing. */
    private static int misclassified(double dist, double pLo, double pHi, int count) {
        Sphere sphere = new Sphere(new Vec3(0, 0, -dist), 1);
        Hit hit = new Hit();
        int wrong = 0;
        for (int i = 0; i < count; i++) {
            double p = pLo + (pHi - pLo) * i / (count - 1);
            if (Math.abs(p - 1) <= 1e-9) {
                continue;
            }
            boolean hits = sphere.intersect(rayPassingAt(p, dist), Double.POSITIVE_INFINITY, hit);
            if (hits != p < 1 || hits && !(Double.isFinite(hit.t) && hit.normal().z() > 0)) {
                wrong++;
            }
        }
        return wrong;
    }

    @Test
    void tangentRayNum03bGivesAMissOrTheExactTangentPointNeverNaN() {
        Sphere sphere = new Sphere(new Vec3(0, 0, -5), 1);
        Hit hit = new Hit();

        if (sphere.intersect(new Ray(0, 1, 0, 0, 0, -1), Double.POSITIVE_INFINITY, hit)) {
            assertEquals(5.0, hit.t, 1e-12);
            assertVec(new Vec3(0, 1, 0), hit.normal(), 1e-12);
        }
        assertEquals(sphere.intersect(new Ray(0, 1, 0, 0, 0, -1), Double.POSITIVE_INFINITY, new Hit()),
                sphere.occluded(new Ray(0, 1, 0, 0, 0, -1), Double.POSITIVE_INFINITY));
    }

    @Test
    void slabNum04Case1RayInAFacePlaneOfATinyBoxHits() {
        Vec3 min = new Vec3(3.223, 0.241, 2.119), max = new Vec3(3.225, 0.243, 2.121);
        Box box = new Box(min.plus(max).times(0.5), max.minus(min));
        Hit hit = new Hit();

        assertTrue(box.intersect(new Ray(3.225, 0.243, 2.221, 0, 0, -1), Double.POSITIVE_INFINITY, hit));

        assertEquals(0.1, hit.t, 1e-12);
        assertVec(new Vec3(0, 0, 1), hit.normal(), 0.0);
        assertTrue(hit.point().isFinite());
    }

    @Test
    void slabNum04Cases2And3RayInAFacePlaneOfTheUnitCubeHitsAtTwo() {
        Box box = new Box(new Vec3(0.5, 0.5, 0.5), new Vec3(1, 1, 1));
        double[][] origins = {{0.5, 1, 3}, {0, 0.5, 3}};
        for (double[] o : origins) {
            Hit hit = new Hit();
            Ray ray = new Ray(o[0], o[1], o[2], 0, 0, -1);

            assertTrue(box.intersect(ray, Double.POSITIVE_INFINITY, hit), ray.toString());

            assertEquals(2.0, hit.t, 0.0);
            assertVec(new Vec3(0, 0, 1), hit.normal(), 0.0);
            assertVec(new Vec3(o[0], o[1], 1), hit.point(), 0.0);
            assertTrue(box.occluded(ray, Double.POSITIVE_INFINITY));
        }
    }

    @Test
    void slabNum04Case4RayOutsideTheFacePlaneMisses() {
        Box box = new Box(new Vec3(0.5, 0.5, 0.5), new Vec3(1, 1, 1));
        Ray ray = new Ray(0.5, 1.5, 3, 0, 0, -1);

        assertFalse(box.intersect(ray, Double.POSITIVE_INFINITY, new Hit()));
        assertFalse(box.occluded(ray, Double.POSITIVE_INFINITY));
    }

    @Test
    void planeNum07ParallelInPlaneAndNearlyParallelRaysMiss() {
        Plane plane = new Plane(Vec3.ZERO, new Vec3(0, 1, 0));
        Ray[] rays = {new Ray(0, 1, 0, 1, 0, 0), new Ray(0, -1, 0, 1, 0, 0), new Ray(0, 0, 0, 1, 0, 0),
                new Ray(0, 1, 0, 1, -1e-310, 0)};
        for (Ray ray : rays) {
            Hit hit = GeometryAssertions.sentinelHit();

            assertFalse(plane.intersect(ray, Double.POSITIVE_INFINITY, hit), ray.toString());
            assertFalse(plane.occluded(ray, Double.POSITIVE_INFINITY), ray.toString());

            GeometryAssertions.assertSentinel(hit);
        }
    }

    @Test
    void planeNum07CameraWhoseCentreRowLiesInThePlaneRendersWithoutNaN() {
        Camera camera = new Camera(Vec3.ZERO, new Vec3(1, 0, 0), new Vec3(0, 1, 0), 60);
        Scene scene = new Scene(camera,
                List.of(new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)),
                        MaterialDefaults.of(MaterialKind.CHALK, new Rgb(0.5, 0.5, 0.5)))),
                List.of(new PointLight(new Vec3(2, 3, 0), Rgb.WHITE, 1, false)), new Rgb(0, 0, 1), 0.1);

        RenderResult result = Renderer.render(RenderRequest.of(scene, new RenderSettings(5, 5, new RegularSampler(1), 4, 1)));

        // The camera sits in the plane: every ray starts on it and leaves it, so every pixel is background.
        assertEquals(0, result.nonFiniteSamples());
        for (int y = 0; y < 5; y++) {
            for (int x = 0; x < 5; x++) {
                assertEquals(0.0, result.film().get(x, y, 0), 0.0, "pixel " + x + "," + y);
                assertEquals(1.0, result.film().get(x, y, 2), 0.0, "pixel " + x + "," + y);
            }
        }
    }

    @Test
    void insideSphereNum10EveryFibonacciDirectionExitsAtTheExactDistance() {
        Sphere sphere = new Sphere(Vec3.ZERO, 1);
        for (Vec3 o : new Vec3[] {Vec3.ZERO, new Vec3(0.3, -0.2, 0.1)}) {
            for (Vec3 d : fibonacciSphere(1000)) {
                Hit hit = new Hit();

                assertTrue(sphere.intersect(new Ray(o, d), Double.POSITIVE_INFINITY, hit), "from " + o + " along " + d);

                double b = o.dot(d);
                double exact = -b + Math.sqrt(b * b + 1 - o.lengthSquared());
                assertEquals(exact, hit.t, 1e-12);
                assertTrue(d.dot(hit.normal()) > 0, "reported as exiting");
            }
        }
    }

    @Test
    void insideBoxNum10EveryFibonacciDirectionExitsAtTheExactDistance() {
        Box box = new Box(Vec3.ZERO, new Vec3(2, 2, 2));
        for (Vec3 o : new Vec3[] {Vec3.ZERO, new Vec3(0.3, -0.2, 0.1)}) {
            for (Vec3 d : fibonacciSphere(1000)) {
                Hit hit = new Hit();

                assertTrue(box.intersect(new Ray(o, d), Double.POSITIVE_INFINITY, hit), "from " + o + " along " + d);

                double exact = Double.POSITIVE_INFINITY;
                for (int axis = 0; axis < 3; axis++) {
                    double di = d.get(axis);
                    if (di != 0) {
                        exact = Math.min(exact, (Math.signum(di) - o.get(axis)) / di);
                    }
                }
                assertEquals(exact, hit.t, 1e-12);
                assertTrue(d.dot(hit.normal()) > 0, "reported as exiting");
                assertEquals(1.0, hit.normal().length(), 1e-15);
            }
        }
    }

    static Vec3[] fibonacciSphere(int n) {
        Vec3[] directions = new Vec3[n];
        double golden = Math.PI * (3 - Math.sqrt(5));
        for (int i = 0; i < n; i++) {
            double z = 1 - (2 * i + 1.0) / n, r = Math.sqrt(1 - z * z), phi = i * golden;
            directions[i] = new Vec3(r * Math.cos(phi), r * Math.sin(phi), z);
        }
        return directions;
    }
}

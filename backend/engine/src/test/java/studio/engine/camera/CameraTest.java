package studio.engine.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;

import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Sphere;
import studio.engine.light.PointLight;
import studio.engine.material.Material;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.render.Film;
import studio.engine.render.RenderResult;
import studio.engine.render.RenderSettings;
import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.engine.sampler.RegularSampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

class CameraTest {

    private static final Vec3 Y = new Vec3(0, 1, 0);
    private static final Material RED_CHALK = MaterialDefaults.of(MaterialKind.CHALK, new Rgb(1, 0, 0));

    @Test
    void centreRayStartsAtTheCameraAndPointsAtTheTarget() {
        Vec3 position = new Vec3(1, 2, 3);
        Camera camera = new Camera(position, new Vec3(4, 6, 3), new Vec3(0, 0, 1), 45);

        Ray ray = camera.ray(0, 0, 1.5);

        assertEquals(position, ray.origin());
        assertClose(new Vec3(0.6, 0.8, 0), ray.direction(), 1e-15);
    }

    @Test
    void cameraLookingDownNegativeZHasRightAlongXAndUpAlongY() {
        Camera camera = new Camera(Vec3.ZERO, new Vec3(0, 0, -1), Y, 60);

        assertClose(new Vec3(1, 0, 0), camera.right(), 0);
        assertClose(new Vec3(0, 1, 0), camera.upward(), 0);
        assertClose(new Vec3(0, 0, 1), camera.backward(), 0);
        assertTrue(camera.ray(1, 0, 1).direction().x() > 0, "right edge of the image is +x");
        assertTrue(camera.ray(0, 1, 1).direction().y() > 0, "top edge of the image is +y");
    }

    @Test
    void edgeRaysMakeTheAnglesTheFieldOfViewPrescribes() {
        double[] fovs = {1, 30, 60, 90, 120, 170};
        double[] aspects = {0.25, 0.5, 1, 16.0 / 9, 3};
        for (double fov : fovs) {
            Camera camera = new Camera(new Vec3(1, 2, 3), new Vec3(-2, 0.5, 7), Y, fov);
            Vec3 axis = camera.backward().negated();
            double half = Math.toRadians(fov) / 2, tan = Math.tan(half);
            for (double aspect : aspects) {
                Vec3 top = camera.ray(0, 1, aspect).direction();
                Vec3 bottom = camera.ray(0, -1, aspect).direction();
                Vec3 right = camera.ray(1, 0, aspect).direction();
                Vec3 left = camera.ray(-1, 0, aspect).direction();
                Vec3 corner = camera.ray(1, 1, aspect).direction();
                String where = "fov " + fov + ", aspect " + aspect;

                assertEquals(half, angle(axis, top), 1e-12, where);
                assertEquals(half, angle(axis, bottom), 1e-12, where);
                assertEquals(Math.atan(aspect * tan), angle(axis, right), 1e-12, where);
                assertEquals(Math.atan(aspect * tan), angle(axis, left), 1e-12, where);
                assertEquals(Math.atan(Math.hypot(aspect * tan, tan)), angle(axis, corner), 1e-12, where);
                assertTrue(top.dot(camera.upward()) > 0 && bottom.dot(camera.upward()) < 0, where);
                assertTrue(right.dot(camera.right()) > 0 && left.dot(camera.right()) < 0, where);
                assertEquals(0, top.dot(camera.right()), 1e-15, "top-edge ray stays in the vertical plane");
                assertEquals(0, right.dot(camera.upward()), 1e-15, "right-edge ray stays in the horizontal plane");
                assertEquals(1, top.length(), 1e-15);
            }
        }
    }

    @Test
    void cameraBasisIsOrthonormalAndRightHanded() {
        Camera camera = new Camera(new Vec3(1, 2, 3), new Vec3(-2, 0.5, 7), new Vec3(0.1, 1, 0.2), 50);
        Vec3 u = camera.right(), v = camera.upward(), w = camera.backward();

        assertEquals(1, u.length(), 1e-15);
        assertEquals(1, v.length(), 1e-15);
        assertEquals(1, w.length(), 1e-15);
        assertEquals(0, u.dot(v), 1e-15);
        assertEquals(0, v.dot(w), 1e-15);
        assertEquals(0, w.dot(u), 1e-15);
        assertClose(w, u.cross(v), 1e-15);
        assertClose(new Vec3(-3, -1.5, 4).normalized(), w.negated(), 1e-15);
    }

    @Test
    void upParallelToTheViewDirectionIsRejectedWithAClearMessage() {
        for (Vec3 up : new Vec3[] {Y, new Vec3(0, -5, 0), new Vec3(0, 1e-300, 0)}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> new Camera(new Vec3(0, 10, 0), Vec3.ZERO, up, 30), "up " + up);
            assertTrue(e.getMessage().contains("up") && e.getMessage().contains("parallel"), e.getMessage());
        }
    }

    @Test
    void upNearlyParallelToTheViewDirectionGivesAnOrthonormalBasisAndSeesTheSphere() {
        // robustness case CAM-01, with up tilted by 1e-6 rad instead of exactly parallel
        Camera nearlyParallel = new Camera(new Vec3(0, 10, 0), Vec3.ZERO, new Vec3(1e-6, 1, 0), 30);
        Camera sideways = new Camera(new Vec3(0, 10, 0), Vec3.ZERO, new Vec3(0, 0, -1), 30);
        Vec3 u = nearlyParallel.right(), v = nearlyParallel.upward(), w = nearlyParallel.backward();
        assertTrue(u.isFinite() && v.isFinite() && w.isFinite());
        assertEquals(1, u.length(), 1e-12);
        assertEquals(1, v.length(), 1e-12);
        assertEquals(0, u.dot(v), 1e-12);
        assertEquals(0, u.dot(w), 1e-12);
        assertEquals(0, v.dot(w), 1e-12);

        Film film = renderUnitSphere(nearlyParallel);
        Film reference = renderUnitSphere(sideways);

        assertEquals(1.0, film.get(16, 16, 0), 0.0, "the centre pixel shows the sphere");
        assertEquals(spherePixels(reference), spherePixels(film));
        assertEquals(121, spherePixels(film), "sphere pixels (robustness case CAM-01 measured 121)");
    }

    private static Film renderUnitSphere(Camera camera) {
        Scene scene = new Scene(camera,
                List.of(new SceneObject(new Sphere(Vec3.ZERO, 1),
                        MaterialDefaults.of(MaterialKind.FLAT, new Rgb(1, 0, 0)))),
                List.of(), new Rgb(0, 0, 1), 0);
        RenderResult result = Renderer.render(RenderRequest.of(scene, new RenderSettings(33, 33, new RegularSampler(1), 1, 1)));
        assertEquals(0, result.nonFiniteSamples());
        return result.film();
    }

    private static int spherePixels(Film film) {
        int count = 0;
        for (int y = 0; y < film.height(); y++) {
            for (int x = 0; x < film.width(); x++) {
                count += film.get(x, y, 0) == 1 ? 1 : 0;
            }
        }
        return count;
    }

    @Test
    void invalidFieldOfViewPositionAndUpAreRejected() {
        for (double fov : new double[] {0, -1, 180, 200, Double.NaN}) {
            assertThrows(IllegalArgumentException.class,
                    () -> new Camera(Vec3.ZERO, new Vec3(0, 0, -1), Y, fov), "fov " + fov);
        }
        assertThrows(IllegalArgumentException.class, () -> new Camera(Vec3.ZERO, Vec3.ZERO, Y, 60));
        assertThrows(IllegalArgumentException.class, () -> new Camera(Vec3.ZERO, new Vec3(0, 0, -1), Vec3.ZERO, 60));
        assertThrows(IllegalArgumentException.class,
                () -> new Camera(new Vec3(Double.NaN, 0, 0), new Vec3(0, 0, -1), Y, 60));
    }

    @Test
    void tinyFieldOfViewFarFromTheOriginKeepsEveryColumnDistinctAndEvenlySpaced() {
        // robustness case CAM-03 a: fov 1e-3 degrees, 512 columns, camera at 1e9 (and 1e8) looking 1000 units down -z
        for (double at : new double[] {1e9, 1e8}) {
            Camera camera = new Camera(new Vec3(at, at, at), new Vec3(at, at, at - 1000), Y, 1e-3);
            Set<Vec3> directions = new HashSet<>();
            double step = Math.toRadians(1e-3) / 512;
            Vec3 previous = null;
            for (int x = 0; x < 512; x++) {
                Ray ray = camera.ray(2 * (x + 0.5) / 512 - 1, 1 - 2 * (256 + 0.5) / 512, 1.0);
                assertEquals(new Vec3(at, at, at), ray.origin());
                directions.add(ray.direction());
                if (previous != null) {
                    assertEquals(step, angle(previous, ray.direction()), 0.01 * step, "column " + x + " at " + at);
                }
                previous = ray.direction();
            }
            assertEquals(512, directions.size(), "distinct column directions at " + at);
        }
    }

    @Test
    void nearlyStraightFieldOfViewPutsTheEdgeColumnAt89Point9499Degrees() {
        // robustness case CAM-03 b: fov 179.9, 512 x 512; the last column's centre is at ndc 511/512
        Camera camera = new Camera(Vec3.ZERO, new Vec3(0, 0, -1), Y, 179.9);
        Vec3 axis = new Vec3(0, 0, -1);
        double expected = Math.toDegrees(Math.atan(511.0 / 512 * Math.tan(Math.toRadians(89.95))));

        assertEquals(89.949902, expected, 1e-6);
        assertEquals(expected, Math.toDegrees(angle(axis, camera.ray(511.0 / 512, 0, 1).direction())), 1e-6);
        assertEquals(expected, Math.toDegrees(angle(axis, camera.ray(-511.0 / 512, 0, 1).direction())), 1e-6);
        for (int y = 0; y < 512; y++) {
            for (int x = 0; x < 512; x++) {
                Vec3 d = camera.ray(2 * (x + 0.5) / 512 - 1, 1 - 2 * (y + 0.5) / 512, 1).direction();
                assertTrue(d.isFinite() && d.z() < 0, "pixel " + x + "," + y + ": " + d);
            }
        }
    }

    @Test
    void nearlyStraightFieldOfViewRendersASymmetricSceneSymmetrically() {
        Camera camera = new Camera(Vec3.ZERO, new Vec3(0, 0, -1), Y, 179.9);
        // At 179.9 degrees the centre pixel alone spans 77 degrees: put the spheres beside the camera.
        Scene scene = new Scene(camera, List.of(
                new SceneObject(new Sphere(new Vec3(-5, 0, 0), 2), RED_CHALK),
                new SceneObject(new Sphere(new Vec3(5, 0, 0), 2), RED_CHALK),
                new SceneObject(new Plane(new Vec3(0, -1, 0), Y),
                        MaterialDefaults.of(MaterialKind.CHALK, new Rgb(0, 1, 0)))),
                List.of(new PointLight(new Vec3(0, 5, 0), Rgb.WHITE, 1, false)), new Rgb(0, 0, 1), 0.1);

        RenderResult result = Renderer.render(RenderRequest.of(scene, new RenderSettings(512, 512, new RegularSampler(1), 1, 2)));

        assertEquals(0, result.nonFiniteSamples());
        Film film = result.film();
        int sphere = 0;
        for (int y = 0; y < 512; y++) {
            for (int x = 0; x < 256; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(film.get(x, y, c), film.get(511 - x, y, c), 0.0, "pixel " + x + "," + y);
                }
                sphere += film.get(x, y, 0) > 0 ? 1 : 0;
            }
        }
        assertTrue(sphere > 0, "the spheres are in the picture: " + sphere);
    }

    /** The angle between two vectors, accurate also for tiny angles. */
    static double angle(Vec3 a, Vec3 b) {
        return Math.atan2(a.cross(b).length(), a.dot(b));
    }

    static void assertClose(Vec3 expected, Vec3 actual, double tolerance) {
        assertTrue(Math.abs(expected.x() - actual.x()) <= tolerance && Math.abs(expected.y() - actual.y()) <= tolerance
                        && Math.abs(expected.z() - actual.z()) <= tolerance,
                () -> "expected " + expected + " but was " + actual);
    }
}

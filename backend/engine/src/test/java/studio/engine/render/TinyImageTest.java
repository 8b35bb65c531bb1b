package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Ray;
import studio.engine.geometry.Sphere;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.sampler.RegularSampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/**
 * Robustness case IMG-01: 1x1 and 1xN images. Pixel centres are (i + 0.5) / W with a double aspect ratio, so
 * nothing divides by W - 1 or truncates W / H. Camera (0,0,5) looking at the origin, fov 30.
 */
class TinyImageTest {

    private static final Camera CAMERA = new Camera(new Vec3(0, 0, 5), Vec3.ZERO, new Vec3(0, 1, 0), 30);
    private static final Rgb SPHERE = new Rgb(1, 0, 0), BACKGROUND = new Rgb(0, 0, 1);

    @Test
    void oneByOneOneBySevenAndSevenByOneImagesShowTheSphereInTheCentrePixel() {
        for (int[] size : new int[][] {{1, 1}, {1, 7}, {7, 1}}) {
            int w = size[0], h = size[1];

            RenderResult result = render(1, w, h);

            assertEquals(0, result.nonFiniteSamples(), w + "x" + h);
            assertEquals(SPHERE.r(), result.film().get(w / 2, h / 2, 0), 0.0, "centre pixel of " + w + "x" + h);
        }
    }

    @Test
    void oneByOnePixelLooksExactlyAlongTheViewDirection() {
        // A sphere of radius 1e-9 on the axis is seen only by a ray within 2e-10 rad of the view direction.
        RenderResult result = render(1e-9, 1, 1);

        assertEquals(SPHERE.r(), result.film().get(0, 0, 0), 0.0);
        Ray centre = CAMERA.ray(0, 0, 1);
        assertEquals(0, centre.direction().minus(new Vec3(0, 0, -1)).length(), 1e-15);
    }

    @Test
    void everyPixelOfThinImagesShowsWhatItsCentreRayMeets() {
        for (int[] size : new int[][] {{1, 7}, {7, 1}, {2, 7}, {7, 2}, {3, 5}, {5, 3}, {64, 9}, {9, 64}}) {
            int w = size[0], h = size[1];
            double aspect = (double) w / h;
            Film film = render(1, w, h).film();
            int sphere = 0;
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    Ray ray = CAMERA.ray(2 * (x + 0.5) / w - 1, 1 - 2 * (y + 0.5) / h, aspect);
                    double miss = distanceFromOrigin(ray) - 1; // < 0: the ray meets the unit sphere
                    if (Math.abs(miss) < 1e-9) {
                        continue;
                    }
                    double expected = miss < 0 ? SPHERE.r() : BACKGROUND.r();
                    assertEquals(expected, film.get(x, y, 0), 0.0, "pixel " + x + "," + y + " of " + w + "x" + h);
                    sphere += miss < 0 ? 1 : 0;
                }
            }
            assertTrue(sphere > 0, w + "x" + h + " shows the sphere");
        }
    }

    private static double distanceFromOrigin(Ray ray) {
        Vec3 o = ray.origin(), d = ray.direction();
        return o.minus(d.times(o.dot(d) / d.dot(d))).length();
    }

    private static RenderResult render(double radius, int w, int h) {
        Scene scene = new Scene(CAMERA,
                List.of(new SceneObject(new Sphere(Vec3.ZERO, radius), MaterialDefaults.of(MaterialKind.FLAT, SPHERE))),
                List.of(), BACKGROUND, 0.1);
        return Renderer.render(RenderRequest.of(scene, new RenderSettings(w, h, new RegularSampler(1), 1, 1)));
    }
}

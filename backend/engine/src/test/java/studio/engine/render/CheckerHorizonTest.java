package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Srgb;
import studio.engine.math.Vec3;
import studio.engine.sampler.SobolSampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;
import studio.engine.texture.CheckerTexture;

/**
 * Robustness case TEX-01 (docs/robustness.md): a checker plane running to the horizon
 * (scenes/bench/checker-horizon.json) at 480x240 and 16 samples stays within 3 levels of 8 bits
 * (RMSE) of the same plane at 1,024 samples, because each sample averages the checks over its ray
 * cone's footprint; point-sampling the checks instead leaves moiré towards the horizon far above that.
 */
class CheckerHorizonTest {

    static final int WIDTH = 480, HEIGHT = 240;

    /** The scene of scenes/bench/checker-horizon.json. */
    static Scene scene() {
        CheckerTexture checks = new CheckerTexture(Rgb.fromSrgb8(0x11, 0x11, 0x11), Rgb.fromSrgb8(0xee, 0xee, 0xee), 1);
        return new Scene(new Camera(new Vec3(0, 1, 0), new Vec3(0, 0.6, -10), new Vec3(0, 1, 0), 50),
                List.of(new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)),
                        MaterialDefaults.of(MaterialKind.FLAT, Rgb.WHITE).withTexture(checks))),
                List.of(), Rgb.fromSrgb8(0x88, 0xaa, 0xdd), 0);
    }

    /** Rendered as the service renders the scene file: sobol samples, every pixel all of them. */
    private static int[] render(Scene scene, int samples) {
        RenderSettings settings = new RenderSettings(WIDTH, HEIGHT, new SobolSampler(samples), 2, 0, 7L,
                RenderSettings.DEFAULT_MIN_PATH_WEIGHT);
        Film film = Renderer.render(RenderRequest.of(scene, settings)).film();
        int[] bytes = new int[3 * WIDTH * HEIGHT];
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                for (int c = 0; c < 3; c++) {
                    bytes[3 * (y * WIDTH + x) + c] = Srgb.toByte(film.get(x, y, c));
                }
            }
        }
        return bytes;
    }

    /**
     * The naive form: each of 16 samples (jittered 4 x 4) reads the checks at its point (a cone
     * spread of 0).
     */
    private static int[] pointSampled(Scene scene, int samples) {
        Integrator integrator = new Integrator(scene, 2, RenderSettings.DEFAULT_MIN_PATH_WEIGHT);
        Random random = new Random(7);
        Ray ray = new Ray();
        int n = (int) Math.sqrt(samples);
        int[] bytes = new int[3 * WIDTH * HEIGHT];
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                double r = 0, g = 0, b = 0;
                for (int i = 0; i < n; i++) {
                    for (int j = 0; j < n; j++) {
                        double sx = x + (i + random.nextDouble()) / n, sy = y + (j + random.nextDouble()) / n;
                        scene.camera().ray(2 * sx / WIDTH - 1, 1 - 2 * sy / HEIGHT, (double) WIDTH / HEIGHT, ray);
                        integrator.trace(ray, 0, 1);
                        r += integrator.r();
                        g += integrator.g();
                        b += integrator.b();
                    }
                }
                int k = 3 * (y * WIDTH + x);
                bytes[k] = Srgb.toByte(r / (n * n));
                bytes[k + 1] = Srgb.toByte(g / (n * n));
                bytes[k + 2] = Srgb.toByte(b / (n * n));
            }
        }
        return bytes;
    }

    static double rmse(int[] a, int[] b) {
        double sum = 0;
        for (int i = 0; i < a.length; i++) {
            double d = a[i] - b[i];
            sum += d * d;
        }
        return Math.sqrt(sum / a.length);
    }

    @Test
    void sixteenFilteredSamplesAreWithinThreeLevelsOfAThousand() {
        Scene scene = scene();
        int[] reference = render(scene, 1024);
        double filtered = rmse(render(scene, 16), reference);
        double naive = rmse(pointSampled(scene, 16), reference);
        System.out.printf("checker horizon 480x240: RMSE against 1024 samples, 8-bit levels: filtered %.3f, "
                + "point-sampled %.3f%n", filtered, naive);
        assertTrue(filtered <= 3, "filtered 16 samples: RMSE " + filtered);
        assertTrue(naive > 3, "point sampling should fail the bound here (the case is not a test of anything "
                + "otherwise): RMSE " + naive);
    }
}

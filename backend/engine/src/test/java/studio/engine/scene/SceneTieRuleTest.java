package studio.engine.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Hit;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Ray;
import studio.engine.light.PointLight;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.render.Film;
import studio.engine.render.RenderSettings;
import studio.engine.render.RenderRequest;
import studio.engine.render.Renderer;
import studio.engine.sampler.RegularSampler;

/**
 * Robustness case NUM-12: the plane y=0 and the top face of the box [-1,1]x[-1,0]x[-1,1] coincide. Hits within
 * {@link Scene#TIE} of each other are a tie and the first-declared object wins, every time.
 */
class SceneTieRuleTest {

    private static final int SIZE = 256;
    private static final Camera CAMERA = new Camera(new Vec3(0.3, 1.7, 2.9), Vec3.ZERO, new Vec3(0, 1, 0), 60);
    private static final SceneObject PLANE = new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)),
            MaterialDefaults.of(MaterialKind.FLAT, new Rgb(1, 0, 0)));
    private static final SceneObject BOX = new SceneObject(new Box(new Vec3(0, -0.5, 0), new Vec3(2, 1, 2)),
            MaterialDefaults.of(MaterialKind.FLAT, new Rgb(0, 0, 1)));

    @Test
    void coincidentPlaneDeclaredFirstWinsEveryOverlapPixel() {
        int[] winners = winnersOverOverlap(scene(PLANE, BOX));

        assertTrue(winners[0] > 9000, "overlap pixels found: " + winners[0]);
        assertEquals(0, winners[1], "pixels where the second-declared box won");
    }

    @Test
    void coincidentBoxDeclaredFirstWinsEveryOverlapPixel() {
        int[] winners = winnersOverOverlap(scene(BOX, PLANE));

        assertTrue(winners[0] > 9000, "overlap pixels found: " + winners[0]);
        assertEquals(0, winners[1], "pixels where the second-declared plane won");
    }

    @Test
    void tieRuleLetsAClearlyNearerLaterObjectWin() {
        SceneObject raisedBox = new SceneObject(new Box(new Vec3(0, -0.5 + 1e-6, 0), new Vec3(2, 1, 2)),
                BOX.material());
        Scene scene = scene(PLANE, raisedBox);
        Hit hit = new Hit();

        assertTrue(scene.intersect(new Ray(0.1, 1, 0.2, 0, -1, 0), Double.POSITIVE_INFINITY, hit));

        assertEquals(1, hit.primitive);
        assertEquals(1 - 1e-6, hit.t, 1e-15);
    }

    @Test
    void coincidentSurfacesRenderTheFirstMaterialBitIdenticallyOnOneAndTwoThreads() {
        Scene scene = scene(PLANE, BOX);
        RenderSettings settings = new RenderSettings(SIZE, SIZE, new RegularSampler(1), 2, 1);

        Film single = Renderer.render(RenderRequest.of(scene, settings)).film();
        Film multi = Renderer.render(RenderRequest.of(scene, settings.withThreads(2))).film();

        int blue = 0;
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(Double.doubleToRawLongBits(single.get(x, y, c)),
                            Double.doubleToRawLongBits(multi.get(x, y, c)), "pixel " + x + "," + y);
                }
                if (single.get(x, y, 2) > 0) {
                    blue++;
                }
            }
        }
        assertEquals(0, blue, "the box lies entirely under the plane declared first, so no pixel is blue");
    }

    /**
     * Traces the primary ray of every pixel centre; among pixels whose plane hit has |x|, |z| < 0.99 returns
     * {overlap pixel count, pixels won by the object declared second}.
     */
    private static int[] winnersOverOverlap(Scene scene) {
        Plane plane = (Plane) PLANE.shape();
        Hit planeHit = new Hit(), hit = new Hit();
        int overlap = 0, secondWins = 0;
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                Ray ray = CAMERA.ray(2 * (x + 0.5) / SIZE - 1, 1 - 2 * (y + 0.5) / SIZE, 1.0);
                if (!plane.intersect(ray, Double.POSITIVE_INFINITY, planeHit)
                        || Math.abs(planeHit.px) >= 0.99 || Math.abs(planeHit.pz) >= 0.99) {
                    continue;
                }
                overlap++;
                assertTrue(scene.intersect(ray, Double.POSITIVE_INFINITY, hit));
                if (hit.primitive == 1) {
                    secondWins++;
                }
            }
        }
        return new int[] {overlap, secondWins};
    }

    private static Scene scene(SceneObject first, SceneObject second) {
        return new Scene(CAMERA, List.of(first, second),
                List.of(new PointLight(new Vec3(2, 5, 3), Rgb.WHITE, 1, false)), Rgb.BLACK, 0.1);
    }
}

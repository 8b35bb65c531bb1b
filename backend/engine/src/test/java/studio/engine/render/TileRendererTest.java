package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Sphere;
import studio.engine.light.PointLight;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.sampler.JitteredSampler;
import studio.engine.sampler.SobolSampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;

/**
 * A render is a set of independent tile tasks: tiles rendered by separate workers, in a shuffled
 * order, each worker of its own (no shared edge samples), give the whole render bit for bit, under
 * each sampling strategy. This is what lets another machine render some of a render's tiles.
 */
class TileRendererTest {

    private static final Scene SCENE = new Scene(new Camera(new Vec3(0, 1.2, 5), new Vec3(0, 0.5, 0), new Vec3(0, 1, 0), 40),
            List.of(new SceneObject(new Sphere(new Vec3(-0.7, 0.5, 0), 0.5), MaterialDefaults.of(MaterialKind.GLASS, new Rgb(1, 1, 1))),
                    new SceneObject(new Sphere(new Vec3(0.7, 0.5, 0), 0.5), MaterialDefaults.of(MaterialKind.PLASTIC, new Rgb(0.8, 0.2, 0.1))),
                    new SceneObject(new Box(new Vec3(0, 0.25, -1), new Vec3(0.5, 0.5, 0.5)), MaterialDefaults.of(MaterialKind.MIRROR, new Rgb(0.9, 0.9, 0.9))),
                    new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)), MaterialDefaults.of(MaterialKind.CHALK, new Rgb(0.7, 0.6, 0.5)))),
            List.of(new PointLight(new Vec3(2, 4, 3), new Rgb(1, 1, 1), 1, false)), new Rgb(0.2, 0.3, 0.5), 0.05);

    @Test
    void tilesRenderedApartInAnyOrderGiveTheWholeRenderUnderEachStrategy() {
        List<RenderSettings> strategies = List.of(
                new RenderSettings(70, 50, new JitteredSampler(4), 6, 2, 11, 1.0 / 1024, 0),     // fixed
                new RenderSettings(70, 50, new JitteredSampler(16), 6, 2, 11, 1.0 / 1024, 0.05), // batch-adaptive
                new RenderSettings(70, 50, new SobolSampler(16), 6, 2, 11, 1.0 / 1024, 0.05));   // progressive sobol
        for (RenderSettings settings : strategies) {
            RenderResult whole = Renderer.render(RenderRequest.of(SCENE, settings));

            List<TileRect> tiles = new ArrayList<>(Renderer.tiles(70, 50, 16));
            Collections.shuffle(tiles, new Random(5));
            Film apart = new Film(70, 50);
            long samples = 0;
            for (int i = 0; i < tiles.size(); i++) {
                TileRenderer worker = new TileRenderer(SCENE, settings); // a worker of its own for each tile
                worker.render(TileRequest.whole(apart, tiles.get(i)));
                samples += worker.samples();
            }

            String strategy = settings.sampler() + " adaptive " + settings.adaptiveThreshold();
            assertEquals(whole.samplesTaken(), samples, strategy);
            for (int y = 0; y < 50; y++) {
                for (int x = 0; x < 70; x++) {
                    for (int c = 0; c < 3; c++) {
                        assertEquals(whole.film().get(x, y, c), apart.get(x, y, c), 0.0,
                                strategy + ", pixel " + x + "," + y);
                    }
                }
            }
        }
    }

    @Test
    void anotherTilingGivesTheWholeRenderUnderEachStrategy() {
        for (double threshold : new double[] {0, 0.05}) {
            for (RenderSettings settings : List.of(
                    new RenderSettings(70, 50, new JitteredSampler(16), 6, 2, 11, 1.0 / 1024, threshold),
                    new RenderSettings(70, 50, new SobolSampler(16), 6, 2, 11, 1.0 / 1024, threshold))) {
                RenderResult whole = Renderer.render(RenderRequest.of(SCENE, settings)); // 16-pixel tiles
                Film apart = new Film(70, 50);
                for (TileRect tile : Renderer.tiles(70, 50, 24)) {
                    new TileRenderer(SCENE, settings).render(TileRequest.whole(apart, tile));
                }
                for (int y = 0; y < 50; y++) {
                    for (int x = 0; x < 70; x++) {
                        for (int c = 0; c < 3; c++) {
                            assertEquals(whole.film().get(x, y, c), apart.get(x, y, c), 0.0,
                                    settings.sampler() + " adaptive " + threshold + ", pixel " + x + "," + y);
                        }
                    }
                }
            }
        }
    }

    @Test
    void aTileRenderedIntoAFilmOfItsOwnHasTheWholeRendersPixels() {
        RenderSettings settings = new RenderSettings(70, 50, new SobolSampler(16), 6, 2, 11, 1.0 / 1024, 0.05);
        RenderResult whole = Renderer.render(RenderRequest.of(SCENE, settings));
        for (TileRect tile : Renderer.tiles(70, 50, 16)) {
            Film own = Film.ofTile(tile);
            new TileRenderer(SCENE, settings).render(TileRequest.whole(own, tile));
            assertEquals(tile.width(), own.width());
            for (int y = tile.y(); y < tile.y() + tile.height(); y++) {
                for (int x = tile.x(); x < tile.x() + tile.width(); x++) {
                    for (int c = 0; c < 3; c++) {
                        assertEquals(whole.film().get(x, y, c), own.get(x, y, c), 0.0, "pixel " + x + "," + y);
                    }
                }
            }
        }
    }

    @Test
    void aStoppedWorkerStopsWithinASample() {
        RenderSettings settings = new RenderSettings(32, 32, new JitteredSampler(4), 6, 1, 11, 1.0 / 1024, 0);
        TileRenderer worker = new TileRenderer(SCENE, settings);
        worker.stop();
        assertThrows(RenderCancelledException.class,
                () -> worker.render(TileRequest.whole(new Film(32, 32), new TileRect(0, 0, 32, 32))));
        assertEquals(0, worker.samples());
    }
}

package studio.engine.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
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

/** A mosaic of nested lattices, pass after pass, fills the film with exactly the whole render's pixels. */
class PixelLatticeTest {

    private static final Scene SCENE = new Scene(new Camera(new Vec3(0, 1, 5), new Vec3(0, 0.5, 0), new Vec3(0, 1, 0), 40),
            List.of(new SceneObject(new Sphere(new Vec3(-0.6, 0.5, 0), 0.5), MaterialDefaults.of(MaterialKind.GLASS, new Rgb(1, 1, 1))),
                    new SceneObject(new Sphere(new Vec3(0.6, 0.5, 0), 0.5), MaterialDefaults.of(MaterialKind.MIRROR, new Rgb(0.9, 0.9, 0.9))),
                    new SceneObject(new Plane(Vec3.ZERO, new Vec3(0, 1, 0)), MaterialDefaults.of(MaterialKind.CHALK, new Rgb(0.7, 0.6, 0.5)))),
            List.of(new PointLight(new Vec3(2, 4, 3), new Rgb(1, 1, 1), 1, false)), new Rgb(0.2, 0.3, 0.5), 0.05);

    @Test
    void nestedLatticesRenderedInTurnGiveTheWholeRenderBitForBit() {
        // an odd size, so the last row and column of blocks are partial
        for (int samples : new int[] {1, 4}) {
            RenderSettings settings = new RenderSettings(61, 45, new JitteredSampler(samples), 6, 2, 7, 1.0 / 1024, 0);
            Film whole = Renderer.render(RenderRequest.of(SCENE, settings)).film();

            Film mosaic = new Film(61, 45);
            PixelLattice[] passes = {new PixelLattice(8, 4), new PixelLattice(4, 0), new PixelLattice(2, 0), PixelLattice.ALL};
            PixelLattice before = null;
            for (PixelLattice pass : passes) {
                Renderer.render(RenderRequest.of(SCENE, settings).into(mosaic, pass, before));
                before = pass;
            }

            for (int y = 0; y < 45; y++) {
                for (int x = 0; x < 61; x++) {
                    for (int c = 0; c < 3; c++) {
                        assertEquals(whole.get(x, y, c), mosaic.get(x, y, c), 0.0,
                                samples + " samples, pixel " + x + "," + y + " channel " + c);
                    }
                }
            }
        }
    }

    @Test
    void aPassRendersOnlyItsOwnPixels() {
        RenderSettings settings = new RenderSettings(40, 30, new JitteredSampler(1), 6, 2, 7, 1.0 / 1024, 0);
        Film film = new Film(40, 30);
        PixelLattice coarse = new PixelLattice(8, 4), next = new PixelLattice(4, 0);

        RenderResult first = Renderer.render(RenderRequest.of(SCENE, settings).into(film, coarse, null));
        RenderResult second = Renderer.render(RenderRequest.of(SCENE, settings).into(film, next, coarse));

        assertEquals(5L * 4, first.samplesTaken(), "one pixel of each 8x8 block");
        assertEquals(10L * 8 - 5 * 4, second.samplesTaken(), "every fourth pixel but those already taken");
        int lit = 0;
        for (int y = 0; y < 30; y++) {
            for (int x = 0; x < 40; x++) {
                boolean rendered = next.contains(x, y);
                double sum = film.get(x, y, 0) + film.get(x, y, 1) + film.get(x, y, 2);
                if (!rendered) {
                    assertEquals(0.0, sum, "pixel " + x + "," + y + " is on neither lattice");
                } else if (sum > 0) {
                    lit++;
                }
            }
        }
        assertEquals(80, lit, "every pixel of both passes has a value (the background is not black)");
    }

    @Test
    void latticeArithmetic() {
        PixelLattice coarse = new PixelLattice(8, 4);
        assertEquals(80, coarse.count(640));
        assertEquals(8, coarse.count(61), "4, 12, ..., 60");
        assertEquals(0, coarse.count(4));
        assertEquals(1, coarse.count(5));
        assertEquals(4, coarse.first(0));
        assertEquals(12, coarse.first(5));
        assertEquals(12, coarse.first(12));
        assertTrue(coarse.contains(12, 20));
        assertFalse(coarse.contains(12, 21));
        assertTrue(coarse.within(new PixelLattice(4, 0)));
        assertTrue(coarse.within(PixelLattice.ALL));
        assertFalse(new PixelLattice(4, 0).within(coarse));
        assertFalse(new PixelLattice(8, 0).within(new PixelLattice(4, 2)));
        assertThrows(IllegalArgumentException.class, () -> new PixelLattice(0, 0));
        assertThrows(IllegalArgumentException.class, () -> new PixelLattice(4, 4));
    }

    @Test
    void adaptiveSamplingAndAWrongFilmAreRefused() {
        RenderSettings adaptive = new RenderSettings(16, 16, new SobolSampler(16), 4, 1, 1, 1.0 / 1024, 0.05);
        assertThrows(IllegalArgumentException.class, () -> Renderer.render(RenderRequest.of(SCENE, adaptive).into(new Film(16, 16), new PixelLattice(2, 0), null)));
        RenderSettings fixed = adaptive.withAdaptiveThreshold(0);
        assertThrows(IllegalArgumentException.class, () -> Renderer.render(RenderRequest.of(SCENE, fixed).into(new Film(8, 16), PixelLattice.ALL, null)));
    }
}

package studio.server.preview;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import studio.engine.render.PixelLattice;
import studio.engine.render.RenderSettings;
import studio.engine.sampler.JitteredSampler;
import studio.engine.sampler.SobolSampler;

/** The live view's refinement plan: a one-sample mosaic, each lattice within the next, then the scene's own settings. */
class PreviewPassTest {

    @Test
    void aViewRefinesThroughTheMosaicThenToTheScenesOwnSamples() {
        RenderSettings target = new RenderSettings(640, 480, new SobolSampler(16), 6, 2, 3, 1.0 / 1024, 0.05);

        List<PreviewPass> passes = PreviewPass.plan(target);

        assertEquals(List.of("80x60", "160x120", "320x240", "640x480", "640x480"),
                passes.stream().map(p -> p.frameWidth() + "x" + p.frameHeight()).toList());
        assertEquals(new PixelLattice(8, 4), passes.get(0).pixels(), "the coarsest lattice sits at its blocks' centres");
        assertNull(passes.get(0).except());
        for (int i = 1; i < 4; i++) {
            PreviewPass pass = passes.get(i);
            assertSame(passes.get(i - 1).pixels(), pass.except(), "pass " + pass.number() + " renders only new pixels");
            assertTrue(pass.except().within(pass.pixels()), "pass " + pass.number() + "'s frame holds the pixels before");
            assertEquals(1, pass.settings().sampler().samplesPerPixel());
            assertEquals(0, pass.settings().adaptiveThreshold());
            assertEquals(640, pass.settings().width(), "every mosaic pass renders into the view-sized film");
            assertFalse(pass.last());
        }
        PreviewPass last = passes.get(4);
        assertSame(target, last.settings());
        assertEquals(PixelLattice.ALL, last.pixels());
        assertNull(last.except(), "the final pass renders its own film");
        assertTrue(last.last());
        assertEquals(List.of(1, 2, 3, 4, 5), passes.stream().map(PreviewPass::number).toList());
    }

    @Test
    void aOneSampleSceneEndsWithItsMosaic() {
        // without a threshold, and with one (the default sampling at render.samples 1: one sample leaves nothing to adapt)
        for (RenderSettings target : List.of(
                new RenderSettings(640, 480, new JitteredSampler(1), 6, 2, 3, 1.0 / 1024, 0),
                new RenderSettings(640, 480, new SobolSampler(1), 6, 2, 3, 1.0 / 1024, 0.05))) {
            List<PreviewPass> passes = PreviewPass.plan(target);

            assertEquals(4, passes.size(), target.toString());
            assertTrue(passes.get(3).last(), "the whole one-sample film is the render itself");
            assertEquals(PixelLattice.ALL, passes.get(3).pixels());
        }
    }

    @Test
    void smallViewsSkipLatticesThatWouldBeEmptyOrNoCoarser() {
        RenderSettings tiny = new RenderSettings(3, 3, new JitteredSampler(4), 6, 1, 3, 1.0 / 1024, 0);
        List<PreviewPass> passes = PreviewPass.plan(tiny);
        assertEquals(List.of("1x1", "3x3", "3x3"), passes.stream().map(p -> p.frameWidth() + "x" + p.frameHeight()).toList());
        assertEquals(new PixelLattice(4, 2), passes.get(0).pixels(), "an 8-pixel block has no pixel at 4 in 3 columns");

        RenderSettings single = new RenderSettings(1, 1, new JitteredSampler(4), 6, 1, 3, 1.0 / 1024, 0);
        assertEquals(2, PreviewPass.plan(single).size(), "a one-pixel view: the one-sample pixel, then the target");

        RenderSettings strip = new RenderSettings(640, 1, new JitteredSampler(4), 6, 1, 3, 1.0 / 1024, 0);
        assertEquals(2, PreviewPass.plan(strip).size(), "no lattice of a one-row view has rows");
    }
}

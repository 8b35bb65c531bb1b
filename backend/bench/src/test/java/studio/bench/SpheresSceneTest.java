package studio.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import studio.server.scene.compiling.SceneMapper;
import studio.server.scene.format.SceneDto;
import studio.server.scene.format.SceneLimits;

class SpheresSceneTest {

    @Test
    void hasTenThousandSpheresWithinTheServersObjectLimit() {
        SceneDto dto = TestRenders.read(SpheresScene.json(100));
        assertEquals(10_000, dto.objects().size());
        assertTrue(dto.objects().size() <= SceneLimits.DEFAULTS.maxObjects());
        // the CLI maps it (limits and all) without a problem
        new SceneMapper(SceneLimits.DEFAULTS).map(dto, 1);
    }

    @Test
    void isTheSameEveryTime() {
        assertEquals(SpheresScene.json(20), SpheresScene.json(20));
    }

    @Test
    void everySphereIsInView() {
        // the whole grid is framed: a small version's mask (ours) touches no image edge but the bottom
        var image = TestRenders.ours(new String(PeerScene.maskJson(SpheresScene.json(100).getBytes())), 160, 120);
        boolean[] mask = Masks.mask(image);
        for (int x = 0; x < 160; x++) {
            assertTrue(!mask[x], "top row, column " + x);
        }
        for (int y = 0; y < 120; y++) {
            assertTrue(!mask[y * 160] && !mask[y * 160 + 159], "left or right edge, row " + y);
        }
    }
}

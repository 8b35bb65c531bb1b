package studio.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;

import studio.server.scene.LightDto;
import studio.server.scene.MaterialDto;
import studio.server.scene.ObjectDto;
import studio.server.scene.SceneDto;

class PeerSceneTest {

    @Test
    void maskJsonMakesObjectsFlatWhitePlanesBlackAndRemovesTheLights() {
        String json = """
                { "name": "m", "background": "#123456",
                  "lights": [ { "type": "point", "position": [1, 2, 3] } ],
                  "objects": [ { "type": "sphere", "material": { "type": "glass", "ior": 1.3 } },
                               { "type": "plane" },
                               { "type": "box", "size": [1, 2, 3] } ] }
                """;
        SceneDto mask = TestRenders.read(new String(PeerScene.maskJson(json.getBytes(StandardCharsets.UTF_8)),
                StandardCharsets.UTF_8));
        assertEquals("#000000", mask.background());
        assertEquals(java.util.List.<LightDto>of(), mask.lights());
        assertEquals(new MaterialDto.Flat("#ffffff"), mask.objects().get(0).material());
        assertEquals(new MaterialDto.Flat("#000000"), mask.objects().get(1).material());
        assertEquals(new MaterialDto.Flat("#ffffff"), mask.objects().get(2).material());
        assertEquals(java.util.List.of(1.0, 2.0, 3.0), ((ObjectDto.Box) mask.objects().get(2)).size());
    }

    @Test
    void resolvedMaskMatchesTheMaskJson() {
        String json = """
                { "objects": [ { "type": "sphere" }, { "type": "plane" } ] }
                """;
        ResolvedScene mask = ResolvedScene.of(TestRenders.read(json), 8, 6).asMask();
        assertEquals(ResolvedScene.MASK_MATERIAL, mask.objects().get(0).material());
        assertEquals(ResolvedScene.MASK_PLANE_MATERIAL, mask.objects().get(1).material());
        assertEquals(0, mask.lights().size());
        assertEquals(studio.engine.math.Rgb.BLACK, mask.background());
    }
}

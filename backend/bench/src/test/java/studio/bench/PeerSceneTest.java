package studio.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import jakarta.validation.Validation;
import jakarta.validation.ValidatorFactory;

import studio.server.scene.format.LightDto;
import studio.server.scene.format.MaterialDto;
import studio.server.scene.format.ObjectDto;
import studio.server.scene.format.SceneDto;
import studio.server.scene.reading.SceneReader;

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

    /** A scene file from elsewhere whose mesh is a file: the file is copied beside our copy of the scene. */
    @Test
    void meshFilesAreReadFromTheScenesFolderAndCopiedBesideOurCopy(@TempDir Path tmp) throws Exception {
        Path scenes = Files.createDirectories(tmp.resolve("scenes/meshes"));
        Files.writeString(scenes.resolve("tri.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        String json = """
                { "objects": [ { "type": "mesh", "file": "meshes/tri.obj", "scale": 2 } ] }
                """;
        Path work = tmp.resolve("work/tri");
        Renderers renderers = new Renderers(Path.of("java"), Path.of("studio.jar"), Path.of("povray"),
                Path.of("sunflow.jar"), tmp, 80, 60, 1);
        PeerScene scene;
        try (ValidatorFactory validation = Validation.buildDefaultValidatorFactory()) {
            scene = PeerScene.write("tri", json.getBytes(StandardCharsets.UTF_8),
                    new SceneReader(validation.getValidator()), work, renderers, List.of(1), tmp.resolve("scenes"));
        }
        assertEquals(Files.readString(scenes.resolve("tri.obj")), Files.readString(work.resolve("meshes/tri.obj")));
        assertTrue(Files.readString(scene.pov()).contains("face_indices { 1,\n    <0,1,2> }\n  scale 2 translate <0, 0, 0>"));
        assertTrue(Files.readString(scene.sunflow().get(1)).contains("geometry object0.geometry triangle_mesh"));
        assertEquals(1, ((ResolvedScene.Mesh) scene.scene().objects().get(0)).mesh().triangleCount());
    }
}

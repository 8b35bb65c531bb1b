package studio.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import studio.engine.geometry.TriangleMesh;
import studio.engine.mesh.MeshData;
import studio.engine.mesh.ObjReader;
import studio.server.scene.compiling.MeshFiles;
import studio.server.scene.compiling.SceneMapper;
import studio.server.scene.format.ObjectDto;
import studio.server.scene.format.SceneDto;
import studio.server.scene.format.SceneLimits;

/** The mesh-100k scene: its mesh, its files, and the same silhouette drawn by ours, POV-Ray and Sunflow. */
class MeshSceneTest {

    static final int W = 200, H = 150;

    @TempDir
    static Path dir;
    static MeshData mesh;
    static String json;

    /** The scene as the peer benchmark writes it: the OBJ file beside the scene file. */
    @BeforeAll
    static void writeScene() throws Exception {
        mesh = MeshScene.mesh();
        MeshScene.writeObj(mesh, dir.resolve(MeshScene.OBJ_FILE));
        json = MeshScene.json(MeshScene.OBJ_FILE);
    }

    @Test
    void knotHasOverAHundredThousandSmoothTriangles() {
        assertEquals(2 * MeshScene.SEGMENTS * MeshScene.SIDES, mesh.triangleCount());
        assertTrue(mesh.triangleCount() >= 100_000);
        assertTrue(mesh.hasNormals());
    }

    @Test
    void objFileReadsBackAsTheSameMeshToSixDecimals() throws Exception {
        MeshData read = ObjReader.parse(Files.readString(dir.resolve(MeshScene.OBJ_FILE), StandardCharsets.UTF_8));
        assertEquals(mesh.vertexCount(), read.vertexCount());
        assertEquals(mesh.triangleCount(), read.triangleCount());
        assertTrue(read.hasNormals());
        for (int i = 0; i < mesh.positions().length; i++) {
            assertEquals(mesh.positions()[i], read.positions()[i], 5e-7);
        }
        assertEquals(java.util.Arrays.toString(mesh.indices()), java.util.Arrays.toString(read.indices()));
    }

    @Test
    void sceneFileNamesTheMeshFileAndTheCliMapsIt() {
        SceneDto dto = TestRenders.read(json);
        ObjectDto.Mesh knot = (ObjectDto.Mesh) dto.objects().get(0);
        assertEquals(MeshScene.OBJ_FILE, knot.file());
        assertEquals(null, knot.obj());
        assertTrue(dto.objects().get(1) instanceof ObjectDto.Plane);
        // within the CLI's limits, the file read beside the scene file
        var compiled = new SceneMapper(SceneLimits.DEFAULTS).map(dto, 1, MeshFiles.in(dir));
        TriangleMesh placed = (TriangleMesh) compiled.scene().shape(0);
        assertEquals(mesh.triangleCount(), placed.triangleCount());
        assertTrue(placed.bounds().minY() > 0.05, "the knot floats above the ground: " + placed.bounds());
    }

    @Test
    void resolvedMeshKeepsItsPlacementForTheExporters() {
        ResolvedScene scene = ResolvedScene.of(TestRenders.read(json), W, H, MeshFiles.in(dir));
        ResolvedScene.Mesh knot = (ResolvedScene.Mesh) scene.objects().get(0);
        assertEquals(new studio.engine.math.Vec3(0, 1.6, 0), knot.position());
        assertEquals(0.8, knot.scale());
        assertEquals(new studio.engine.math.Vec3(-20, 25, 15), knot.rotationDegrees());
        assertEquals(mesh.triangleCount(), knot.mesh().triangleCount());
        assertTrue(scene.objects().get(1) instanceof ResolvedScene.Plane);
    }

    /**
     * The benchmark's mask check on the real scene, small: ours (the CLI's mapping, file beside the
     * scene), POV-Ray's mesh2 and Sunflow's triangle_mesh agree on at least 99% of the pixels.
     */
    @Test
    void oursPovrayAndSunflowDrawTheSameKnot(@TempDir Path work) throws Exception {
        ResolvedScene mask = ResolvedScene.of(TestRenders.read(json), W, H, MeshFiles.in(dir)).asMask();
        String maskJson = new String(PeerScene.maskJson(json.getBytes(StandardCharsets.UTF_8)), StandardCharsets.UTF_8);
        BufferedImage ours = TestRenders.ours(maskJson, W, H, MeshFiles.in(dir));
        boolean[] oursMask = Masks.mask(ours);
        assertTrue(Masks.coverage(oursMask) > 0.08, "the knot is in view: " + Masks.coverage(oursMask));
        for (int x = 0; x < W; x++) {
            assertTrue(!oursMask[x] && !oursMask[(H - 1) * W + x], "the knot is not cut off, column " + x);
        }
        BufferedImage povray = TestRenders.povray(PovrayScene.of(mask, "mesh-100k, mask"), W, H, work);
        BufferedImage sunflow = TestRenders.sunflow(SunflowScene.of(mask, 0, 1), work);
        MaskCheck check = MaskCheck.of(oursMask, Masks.mask(povray), Masks.mask(sunflow));
        assertTrue(check.agreementPovray() >= Masks.REQUIRED, "POV-Ray: " + check);
        assertTrue(check.agreementSunflow() >= Masks.REQUIRED, "Sunflow: " + check);
        assertTrue(check.iouPovray() >= 0.97 && check.iouSunflow() >= 0.97, check.toString());
    }
}

package studio.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import studio.engine.geometry.TriangleMesh;
import studio.engine.math.Rotation;
import studio.engine.math.Vec3;
import studio.engine.mesh.MeshData;
import studio.engine.mesh.MeshShapes;

/**
 * Boxes are rotated as ours are by both peers. Ours is R = Rx Ry Rz (three.js order 'XYZ'), which turns
 * a point about z first; POV-Ray applies {@code rotate} in the order written, so the exporter writes
 * z, then y, then x. Checked on the matrices and on rendered silhouettes.
 */
class RotationOrderTest {

    /** A box rotated about all three axes, and a sphere to anchor the framing; no ground plane. */
    static final String SCENE = """
            { "name": "rotated-box", "camera": { "position": [0.5, 2.5, 5], "lookAt": [0, 0.4, 0], "fov": 45 },
              "objects": [
                { "type": "box", "center": [0, 0.5, 0], "size": [2.2, 0.9, 0.35], "rotation": [30, 45, 60],
                  "material": { "type": "plastic", "color": "#cc3333" } },
                { "type": "sphere", "center": [-1.7, 0.4, -0.5], "radius": 0.4 } ] }
            """;
    static final int W = 240, H = 180;

    /**
     * POV-Ray's rotate matrices as in its source (Compute_Rotation_Transform, row vectors, p' = p M):
     * about x, y' = y cos - z sin and z' = y sin + z cos; likewise about y and z. Numerically the
     * right-handed rotations: POV-Ray's "left-handed" rotation is the same matrix seen in a mirrored frame.
     */
    static Vec3 povrayRotate(Vec3 p, char axis, double degrees) {
        double c = Math.cos(Math.toRadians(degrees)), s = Math.sin(Math.toRadians(degrees));
        return switch (axis) {
            case 'x' -> new Vec3(p.x(), p.y() * c - p.z() * s, p.y() * s + p.z() * c);
            case 'y' -> new Vec3(p.x() * c + p.z() * s, p.y(), -p.x() * s + p.z() * c);
            default -> new Vec3(p.x() * c - p.y() * s, p.x() * s + p.y() * c, p.z());
        };
    }

    @Test
    void rotatingAboutZThenYThenXIsOurEulerRotation() {
        Random random = new Random(7);
        for (int i = 0; i < 200; i++) {
            Vec3 angles = new Vec3(360 * random.nextDouble() - 180, 360 * random.nextDouble() - 180,
                    360 * random.nextDouble() - 180);
            Vec3 p = new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian());
            Vec3 ours = Rotation.fromEulerDegrees(angles).apply(p);
            Vec3 povray = povrayRotate(povrayRotate(povrayRotate(p, 'z', angles.z()), 'y', angles.y()), 'x', angles.x());
            assertEquals(0, ours.minus(povray).length(), 1e-12, "angles " + angles);
        }
    }

    @Test
    void sunflowsBoxTransformIsOurRotationAndCentre() {
        ResolvedScene.Box box = new ResolvedScene.Box(new Vec3(1, 2, 3), new Vec3(1, 1, 1), new Vec3(30, 45, 60),
                ResolvedScene.MASK_MATERIAL);
        double[] m = SunflowScene.boxTransform(box);
        Vec3 p = new Vec3(0.3, -0.2, 0.7);
        Vec3 expected = Rotation.fromEulerDegrees(box.rotationDegrees()).apply(p).plus(box.center());
        Vec3 actual = new Vec3(m[0] * p.x() + m[1] * p.y() + m[2] * p.z() + m[3],
                m[4] * p.x() + m[5] * p.y() + m[6] * p.z() + m[7], m[8] * p.x() + m[9] * p.y() + m[10] * p.z() + m[11]);
        assertEquals(0, expected.minus(actual).length(), 1e-12);
    }

    /**
     * A mesh is placed as the engine places it (scale, then rotate Rx Ry Rz, then move): Sunflow's
     * instance matrix and POV-Ray's {@code scale s rotate z rotate y rotate x translate p} both give
     * TriangleMesh's world-space vertices.
     */
    @Test
    void meshTransformsAreTheEnginesPlacement() {
        MeshData data = MeshShapes.torusKnot(2, 3, 24, 6);
        Vec3 position = new Vec3(1, -2, 0.5), rotation = new Vec3(30, 45, 60);
        double scale = 0.7;
        double[] world = new TriangleMesh(data, position, scale, rotation).positions();
        double[] m = SunflowScene.transform(position, rotation, scale);
        double[] p = data.positions();
        for (int i = 0; i < p.length; i += 3) {
            Vec3 engine = new Vec3(world[i], world[i + 1], world[i + 2]);
            Vec3 sunflow = new Vec3(m[0] * p[i] + m[1] * p[i + 1] + m[2] * p[i + 2] + m[3],
                    m[4] * p[i] + m[5] * p[i + 1] + m[6] * p[i + 2] + m[7],
                    m[8] * p[i] + m[9] * p[i + 1] + m[10] * p[i + 2] + m[11]);
            Vec3 povray = povrayRotate(povrayRotate(povrayRotate(new Vec3(p[i], p[i + 1], p[i + 2]).times(scale), 'z',
                    rotation.z()), 'y', rotation.y()), 'x', rotation.x()).plus(position);
            assertEquals(0, engine.minus(sunflow).length(), 1e-12, "vertex " + i / 3);
            assertEquals(0, engine.minus(povray).length(), 1e-12, "vertex " + i / 3);
        }
    }

    @Test
    void povraysRotatedBoxHasOurSilhouette(@TempDir Path dir) throws Exception {
        ResolvedScene mask = ResolvedScene.of(TestRenders.read(SCENE), W, H).asMask();
        String sdl = PovrayScene.of(mask, "rotated box");
        BufferedImage ours = TestRenders.ours(maskJson(), W, H);
        BufferedImage povray = TestRenders.povray(sdl, W, H, dir);
        assertTrue(Masks.agreement(ours, povray) >= 0.999, "agreement " + Masks.agreement(ours, povray));

        // the check can tell: the other order (x, then y, then z) would fail the benchmark's mask check
        String wrongOrder = sdl.replace("rotate z*60 rotate y*45 rotate x*30", "rotate x*30 rotate y*45 rotate z*60");
        assertTrue(!wrongOrder.equals(sdl));
        BufferedImage wrong = TestRenders.povray(wrongOrder, W, H, dir);
        assertTrue(Masks.agreement(ours, wrong) < Masks.REQUIRED, "agreement with the wrong order "
                + Masks.agreement(ours, wrong));
        assertTrue(Masks.intersectionOverUnion(Masks.mask(ours), Masks.mask(wrong)) < 0.9);
        assertTrue(Masks.intersectionOverUnion(Masks.mask(ours), Masks.mask(povray)) >= 0.99);
    }

    @Test
    void sunflowsRotatedBoxHasOurSilhouette(@TempDir Path dir) throws Exception {
        ResolvedScene mask = ResolvedScene.of(TestRenders.read(SCENE), W, H).asMask();
        BufferedImage ours = TestRenders.ours(maskJson(), W, H);
        BufferedImage sunflow = TestRenders.sunflow(SunflowScene.of(mask, 0, 1), dir);
        assertTrue(Masks.agreement(ours, sunflow) >= 0.99, "agreement " + Masks.agreement(ours, sunflow));
    }

    private static String maskJson() {
        return new String(PeerScene.maskJson(SCENE.getBytes(StandardCharsets.UTF_8)), StandardCharsets.UTF_8);
    }
}

package studio.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import studio.engine.math.Rgb;
import studio.engine.math.Vec3;

class MeshGeneratorTest {

    @Test
    void benchmarkMeshHasOverAHundredThousandTriangles() {
        MeshData mesh = MeshGenerator.bumpySphere(new Vec3(0, 1, 0), 1, 0.06, 256, 200);
        assertEquals(2 * 256 * 199, mesh.triangleCount());
        assertTrue(mesh.triangleCount() >= 100_000);
    }

    @Test
    void normalsHaveUnitLengthAndPointOutwards() {
        Vec3 c = new Vec3(1, 2, 3);
        MeshData mesh = MeshGenerator.bumpySphere(c, 2, 0.05, 24, 12);
        double[] p = mesh.positions(), n = mesh.normals();
        for (int v = 0; v < mesh.vertexCount(); v++) {
            Vec3 normal = new Vec3(n[3 * v], n[3 * v + 1], n[3 * v + 2]);
            Vec3 out = new Vec3(p[3 * v], p[3 * v + 1], p[3 * v + 2]).minus(c);
            assertEquals(1, normal.length(), 1e-12);
            assertTrue(normal.dot(out) > 0, "vertex " + v);
        }
        // faces wind counter-clockwise seen from outside: their geometric normal points outwards too
        int[] idx = mesh.indices();
        for (int t = 0; t < idx.length; t += 3) {
            Vec3 a = vertex(p, idx[t]), b = vertex(p, idx[t + 1]), d = vertex(p, idx[t + 2]);
            Vec3 face = b.minus(a).cross(d.minus(a));
            assertTrue(face.dot(a.plus(b).plus(d).times(1.0 / 3).minus(c)) > 0, "triangle " + t / 3);
        }
    }

    @Test
    void objTextHasEveryVertexNormalAndFace() {
        MeshData mesh = MeshGenerator.bumpySphere(Vec3.ZERO, 1, 0, 3, 2);
        String obj = mesh.toObj();
        assertEquals(mesh.vertexCount(), obj.lines().filter(l -> l.startsWith("v ")).count());
        assertEquals(mesh.vertexCount(), obj.lines().filter(l -> l.startsWith("vn ")).count());
        assertEquals(mesh.triangleCount(), obj.lines().filter(l -> l.startsWith("f ")).count());
        assertTrue(obj.contains("\nf 1//1 "), obj);
    }

    /** The mesh exporters agree with each other (ours has no meshes yet): POV-Ray's and Sunflow's masks. */
    @Test
    void povrayAndSunflowDrawTheSameMesh(@TempDir Path dir) throws Exception {
        int w = 200, h = 150;
        ResolvedScene scene = new ResolvedScene(w, h,
                new ResolvedScene.Camera(new Vec3(0.5, 2, 4), new Vec3(0, 1, 0), new Vec3(0, 1, 0), 40), Rgb.BLACK,
                0.1, 4, List.of(), List.of(new ResolvedScene.Mesh(
                        MeshGenerator.bumpySphere(new Vec3(0, 1, 0), 1, 0.08, 64, 48), ResolvedScene.MASK_MATERIAL)));
        BufferedImage povray = TestRenders.povray(PovrayScene.of(scene, "mesh"), w, h, dir);
        BufferedImage sunflow = TestRenders.sunflow(SunflowScene.of(scene, 0, 1), dir);
        boolean[] mask = Masks.mask(povray);
        assertTrue(Masks.coverage(mask) > 0.1, "the mesh is in view");
        assertTrue(Masks.agreement(mask, Masks.mask(sunflow)) >= 0.99,
                "agreement " + Masks.agreement(mask, Masks.mask(sunflow)));
    }

    private static Vec3 vertex(double[] p, int i) {
        return new Vec3(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    }
}

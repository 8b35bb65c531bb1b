package studio.engine.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.Map;

import org.junit.jupiter.api.Test;

/** The generated meshes are closed, consistently wound outwards, and their normals agree with the winding. */
class MeshShapesTest {

    @Test
    void icosphereHasTheExpectedCountsUnitVerticesAndOutwardWinding() {
        for (int s = 0; s <= 4; s++) {
            MeshData mesh = MeshShapes.icosphere(s);

            assertEquals(20 << (2 * s), mesh.triangleCount());
            assertEquals(10 * (1 << (2 * s)) + 2, mesh.vertexCount());
            for (int v = 0; v < mesh.vertexCount(); v++) {
                double[] p = mesh.positions();
                assertEquals(1, Math.sqrt(p[3 * v] * p[3 * v] + p[3 * v + 1] * p[3 * v + 1] + p[3 * v + 2] * p[3 * v + 2]), 1e-15);
            }
            assertClosedAndConsistentlyWound(mesh);
            assertFaceNormalsAgreeWithVertexNormals(mesh);
        }
    }

    @Test
    void torusKnotIsAClosedTubeWithNormalsOnTheWindingSide() {
        MeshData knot = MeshShapes.torusKnot(2, 3, 200, 24);

        assertEquals(2 * 200 * 24, knot.triangleCount());
        assertEquals(200 * 24, knot.vertexCount());
        assertClosedAndConsistentlyWound(knot);
        assertFaceNormalsAgreeWithVertexNormals(knot);
    }

    @Test
    void rejectsSizesThatMakeNoMesh() {
        assertThrows(IllegalArgumentException.class, () -> MeshShapes.torusKnot(2, 3, 2, 10));
        assertThrows(IllegalArgumentException.class, () -> MeshShapes.icosphere(-1));
    }

    /** Every directed edge appears once and its reverse once: closed, and neighbours wound alike. */
    private static void assertClosedAndConsistentlyWound(MeshData mesh) {
        Map<Long, Integer> directed = new HashMap<>();
        int[] f = mesh.indices();
        for (int i = 0; i < f.length; i += 3) {
            for (int k = 0; k < 3; k++) {
                long edge = ((long) f[i + k] << 32) | f[i + (k + 1) % 3];
                directed.merge(edge, 1, Integer::sum);
            }
        }
        for (Map.Entry<Long, Integer> e : directed.entrySet()) {
            long key = e.getKey();
            long reverse = ((key & 0xffffffffL) << 32) | (key >>> 32);
            assertEquals(1, e.getValue(), "directed edge used twice");
            assertEquals(1, directed.getOrDefault(reverse, 0), "edge without its opposite");
        }
    }

    /** The winding's normal points the same way as the corners' vertex normals. */
    private static void assertFaceNormalsAgreeWithVertexNormals(MeshData mesh) {
        double[] p = mesh.positions(), n = mesh.normals();
        int[] f = mesh.indices();
        for (int i = 0; i < f.length; i += 3) {
            int a = 3 * f[i], b = 3 * f[i + 1], c = 3 * f[i + 2];
            double ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
            double vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
            double gx = uy * vz - uz * vy, gy = uz * vx - ux * vz, gz = ux * vy - uy * vx;
            for (int corner : new int[] {a, b, c}) {
                assertTrue(gx * n[corner] + gy * n[corner + 1] + gz * n[corner + 2] > 0, "triangle " + i / 3);
            }
        }
    }
}

package studio.engine.geometry;

import studio.engine.mesh.MeshData;

/**
 * A mesh's nearest hit found by testing each of its triangles as a mesh of its own, one after the
 * other, without the mesh's tree: the reference the tree is checked against (robustness case
 * NUM-06, docs/robustness.md). Built from the mesh's public data (world positions, triangles in the
 * mesh's order, normals), so a triangle's hit is the mesh's own to the bit; of hits at the same
 * distance the triangle listed first wins.
 */
final class EachTriangle {

    private final TriangleMesh[] triangles;

    EachTriangle(TriangleMesh mesh) {
        double[] positions = mesh.positions(), normals = mesh.normals();
        int[] indices = mesh.indices();
        triangles = new TriangleMesh[indices.length / 3];
        for (int t = 0; t < triangles.length; t++) {
            double[] xyz = new double[9];
            double[] n = normals == null ? null : new double[9];
            for (int v = 0; v < 3; v++) {
                System.arraycopy(positions, 3 * indices[3 * t + v], xyz, 3 * v, 3);
                if (n != null) {
                    System.arraycopy(normals, 3 * indices[3 * t + v], n, 3 * v, 3);
                }
            }
            triangles[t] = new TriangleMesh(new MeshData(xyz, new int[] {0, 1, 2}, n));
        }
    }

    /** The nearest hit with 0 &lt; t &lt; tMax over every triangle, filled into {@code hit}. */
    boolean intersect(Ray ray, double tMax, Hit hit) {
        double best = tMax;
        boolean found = false;
        for (TriangleMesh triangle : triangles) {
            if (triangle.intersect(ray, best, hit)) {
                best = hit.t;
                found = true;
            }
        }
        return found;
    }
}

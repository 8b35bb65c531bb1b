package studio.engine.mesh;

/**
 * A triangle mesh in object space, as read from a file or generated: vertex positions (x, y, z per
 * vertex), triangles as three vertex indices each (counter-clockwise seen from outside, as in OBJ),
 * optionally one normal per vertex (x, y, z, non-zero; not necessarily unit length) for smooth
 * shading, or null, and optionally one texture coordinate per vertex (u, v, finite; v up, as OBJ's
 * {@code vt} and three.js have it: a glTF reader passes 1 - v), or null. A mesh without normals or
 * UVs holds no array for them.
 *
 * <p>The arrays are taken as they are, not copied (meshes are large): whoever makes a MeshData
 * hands its arrays over and does not change them afterwards. Record equality is therefore array
 * identity.
 */
public record MeshData(double[] positions, int[] indices, double[] normals, double[] uvs) {

    /** A mesh without texture coordinates. */
    public MeshData(double[] positions, int[] indices, double[] normals) {
        this(positions, indices, normals, null);
    }

    public MeshData {
        if (positions == null || indices == null) {
            throw new IllegalArgumentException("a mesh needs positions and indices");
        }
        if (positions.length % 3 != 0) {
            throw new IllegalArgumentException("positions must hold 3 coordinates per vertex; length " + positions.length);
        }
        if (indices.length % 3 != 0) {
            throw new IllegalArgumentException("indices must hold 3 per triangle; length " + indices.length);
        }
        if (normals != null && normals.length != positions.length) {
            throw new IllegalArgumentException("normals must match positions one to one: " + normals.length
                    + " values for " + positions.length);
        }
        if (uvs != null && uvs.length != positions.length / 3 * 2) {
            throw new IllegalArgumentException("uvs must hold 2 values per vertex: " + uvs.length + " values for "
                    + positions.length / 3 + " vertices");
        }
        if (uvs != null) {
            for (int i = 0; i < uvs.length; i++) {
                if (!Double.isFinite(uvs[i])) {
                    throw new IllegalArgumentException("vertex " + i / 2 + " has a non-finite texture coordinate: "
                            + uvs[i]);
                }
            }
        }
        for (int i = 0; i < positions.length; i++) {
            if (!Double.isFinite(positions[i])) {
                throw new IllegalArgumentException("vertex " + i / 3 + " has a non-finite coordinate: " + positions[i]);
            }
        }
        int vertices = positions.length / 3;
        for (int i = 0; i < indices.length; i++) {
            if (indices[i] < 0 || indices[i] >= vertices) {
                throw new IllegalArgumentException("triangle " + i / 3 + " refers to vertex " + indices[i]
                        + ", but there are " + vertices);
            }
        }
        if (normals != null) {
            for (int v = 0; v < vertices; v++) {
                double x = normals[3 * v], y = normals[3 * v + 1], z = normals[3 * v + 2];
                if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(z) || x == 0 && y == 0 && z == 0) {
                    throw new IllegalArgumentException("vertex " + v + " has a zero or non-finite normal");
                }
            }
        }
    }

    public int vertexCount() {
        return positions.length / 3;
    }

    public int triangleCount() {
        return indices.length / 3;
    }

    public boolean hasNormals() {
        return normals != null;
    }

    public boolean hasUvs() {
        return uvs != null;
    }
}

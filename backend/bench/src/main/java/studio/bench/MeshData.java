package studio.bench;

/**
 * An indexed triangle mesh in world space, as the exporters take it: {@code positions} and
 * {@code normals} hold x, y, z per vertex (normals of unit length, for smooth shading),
 * {@code indices} three vertex indices per triangle, counter-clockwise seen from the front.
 */
public record MeshData(double[] positions, double[] normals, int[] indices) {

    public MeshData {
        if (positions.length % 3 != 0 || normals.length != positions.length || indices.length % 3 != 0) {
            throw new IllegalArgumentException("positions and normals need x, y, z per vertex, indices three per triangle");
        }
        int vertices = positions.length / 3;
        for (int i : indices) {
            if (i < 0 || i >= vertices) {
                throw new IllegalArgumentException("vertex index out of range: " + i);
            }
        }
    }

    public int vertexCount() {
        return positions.length / 3;
    }

    public int triangleCount() {
        return indices.length / 3;
    }

    /** The mesh as Wavefront OBJ text (v, vn, f v//vn), as the scene format's meshes will take it. */
    public String toObj() {
        StringBuilder obj = new StringBuilder(64 * vertexCount() + 32 * triangleCount());
        for (int v = 0; v < vertexCount(); v++) {
            obj.append("v ").append(Sdl.num(positions[3 * v])).append(' ').append(Sdl.num(positions[3 * v + 1]))
                    .append(' ').append(Sdl.num(positions[3 * v + 2])).append('\n');
        }
        for (int v = 0; v < vertexCount(); v++) {
            obj.append("vn ").append(Sdl.num(normals[3 * v])).append(' ').append(Sdl.num(normals[3 * v + 1]))
                    .append(' ').append(Sdl.num(normals[3 * v + 2])).append('\n');
        }
        for (int t = 0; t < triangleCount(); t++) {
            obj.append('f');
            for (int k = 0; k < 3; k++) {
                int i = indices[3 * t + k] + 1;
                obj.append(' ').append(i).append("//").append(i);
            }
            obj.append('\n');
        }
        return obj.toString();
    }
}

package studio.engine.mesh;

/**
 * Closed test and benchmark meshes with vertex normals, counter-clockwise seen from outside:
 * a (p, q) torus knot tube (as three.js's TorusKnotGeometry, without the seam's duplicate
 * vertices) and a subdivided icosahedron projected onto the unit sphere.
 */
public final class MeshShapes {

    /** The standard icosahedron on the unit sphere, 12 vertices (before normalising). */
    private static final double T = (1 + Math.sqrt(5)) / 2;
    private static final double[] ICOSAHEDRON = {
            -1, T, 0, 1, T, 0, -1, -T, 0, 1, -T, 0,
            0, -1, T, 0, 1, T, 0, -1, -T, 0, 1, -T,
            T, 0, -1, T, 0, 1, -T, 0, -1, -T, 0, 1};
    private static final int[] ICOSAHEDRON_FACES = {
            0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11,
            1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
            3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9,
            4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};

    private MeshShapes() {
    }

    /**
     * A tube of radius 0.4 around the (p, q) torus knot of radius 1 (it winds p times around the
     * axis and q times through the hole): {@code 2*segments*sides} triangles, {@code segments*sides}
     * vertices, every vertex normal pointing away from the tube's centre line.
     */
    public static MeshData torusKnot(int p, int q, int segments, int sides) {
        if (p < 1 || q < 1 || segments < 3 || sides < 3 || (long) segments * sides * 2 > Integer.MAX_VALUE / 3) {
            throw new IllegalArgumentException("torus knot needs p, q >= 1, segments, sides >= 3: "
                    + p + ", " + q + ", " + segments + ", " + sides);
        }
        double tube = 0.4;
        int vertices = segments * sides;
        double[] positions = new double[3 * vertices];
        double[] normals = new double[3 * vertices];
        double[] p1 = new double[3], p2 = new double[3];
        for (int j = 0; j < segments; j++) {
            double u = (double) j / segments * p * 2 * Math.PI;
            knot(u, p, q, p1);
            knot(u + 0.01, p, q, p2);
            double tx = p2[0] - p1[0], ty = p2[1] - p1[1], tz = p2[2] - p1[2];
            double nx = p2[0] + p1[0], ny = p2[1] + p1[1], nz = p2[2] + p1[2];
            double bx = ty * nz - tz * ny, by = tz * nx - tx * nz, bz = tx * ny - ty * nx;
            nx = by * tz - bz * ty;
            ny = bz * tx - bx * tz;
            nz = bx * ty - by * tx;
            double bl = Math.sqrt(bx * bx + by * by + bz * bz), nl = Math.sqrt(nx * nx + ny * ny + nz * nz);
            bx /= bl; by /= bl; bz /= bl;
            nx /= nl; ny /= nl; nz /= nl;
            for (int i = 0; i < sides; i++) {
                double v = (double) i / sides * 2 * Math.PI;
                double cx = -Math.cos(v), cy = Math.sin(v);
                double ox = cx * nx + cy * bx, oy = cx * ny + cy * by, oz = cx * nz + cy * bz;
                int k = 3 * (j * sides + i);
                positions[k] = p1[0] + tube * ox;
                positions[k + 1] = p1[1] + tube * oy;
                positions[k + 2] = p1[2] + tube * oz;
                normals[k] = ox;
                normals[k + 1] = oy;
                normals[k + 2] = oz;
            }
        }
        int[] indices = new int[6 * vertices];
        int f = 0;
        for (int j = 0; j < segments; j++) {
            int j1 = (j + 1) % segments;
            for (int i = 0; i < sides; i++) {
                int i1 = (i + 1) % sides;
                int a = j * sides + i, b = j1 * sides + i, c = j1 * sides + i1, d = j * sides + i1;
                indices[f++] = a; indices[f++] = b; indices[f++] = d;
                indices[f++] = b; indices[f++] = c; indices[f++] = d;
            }
        }
        return new MeshData(positions, indices, normals);
    }

    private static void knot(double u, int p, int q, double[] out) {
        double quOverP = (double) q / p * u;
        double cs = Math.cos(quOverP);
        out[0] = (2 + cs) * 0.5 * Math.cos(u);
        out[1] = (2 + cs) * 0.5 * Math.sin(u);
        out[2] = Math.sin(quOverP) * 0.5;
    }

    /**
     * The unit sphere as an icosahedron whose faces are split into 4, {@code subdivisions} times:
     * {@code 20 * 4^subdivisions} triangles; the normals equal the positions.
     */
    public static MeshData icosphere(int subdivisions) {
        if (subdivisions < 0 || subdivisions > 10) {
            throw new IllegalArgumentException("icosphere subdivisions must be 0..10: " + subdivisions);
        }
        int triangles = 20 << (2 * subdivisions);
        int vertices = 10 * (1 << (2 * subdivisions)) + 2;
        double[] positions = new double[3 * vertices];
        for (int v = 0; v < 12; v++) {
            double x = ICOSAHEDRON[3 * v], y = ICOSAHEDRON[3 * v + 1], z = ICOSAHEDRON[3 * v + 2];
            double len = Math.sqrt(x * x + y * y + z * z);
            positions[3 * v] = x / len;
            positions[3 * v + 1] = y / len;
            positions[3 * v + 2] = z / len;
        }
        int vertexCount = 12;
        int[] faces = ICOSAHEDRON_FACES.clone();
        for (int s = 0; s < subdivisions; s++) {
            int[] next = new int[faces.length * 4];
            LongIntMap midpoints = new LongIntMap(faces.length / 2);
            int f = 0;
            for (int t = 0; t < faces.length; t += 3) {
                int a = faces[t], b = faces[t + 1], c = faces[t + 2];
                int ab = midpoint(a, b, positions, vertexCount, midpoints);
                vertexCount += ab == vertexCount ? 1 : 0;
                int bc = midpoint(b, c, positions, vertexCount, midpoints);
                vertexCount += bc == vertexCount ? 1 : 0;
                int ca = midpoint(c, a, positions, vertexCount, midpoints);
                vertexCount += ca == vertexCount ? 1 : 0;
                int[] split = {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca};
                System.arraycopy(split, 0, next, f, 12);
                f += 12;
            }
            faces = next;
        }
        assert faces.length == 3 * triangles && vertexCount == vertices;
        return new MeshData(positions, faces, positions.clone());
    }

    /** The index of the unit-sphere midpoint of edge (a, b), adding it as vertex {@code next} if new. */
    private static int midpoint(int a, int b, double[] positions, int next, LongIntMap midpoints) {
        long key = a < b ? ((long) a << 32) | b : ((long) b << 32) | a;
        int existing = midpoints.get(key);
        if (existing >= 0) {
            return existing;
        }
        double x = positions[3 * a] + positions[3 * b];
        double y = positions[3 * a + 1] + positions[3 * b + 1];
        double z = positions[3 * a + 2] + positions[3 * b + 2];
        double len = Math.sqrt(x * x + y * y + z * z);
        positions[3 * next] = x / len;
        positions[3 * next + 1] = y / len;
        positions[3 * next + 2] = z / len;
        midpoints.putNew(key, next);
        return next;
    }
}

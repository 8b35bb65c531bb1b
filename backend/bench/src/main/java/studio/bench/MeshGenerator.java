package studio.bench;

import studio.engine.math.Vec3;

/**
 * Generated meshes for the benchmark, until the scene format has meshes: a bumpy sphere (a UV
 * sphere whose radius ripples with latitude and longitude), smooth-shaded, in world space.
 */
public final class MeshGenerator {

    private MeshGenerator() {
    }

    /**
     * A bumpy sphere of {@code 2 * segments * (rings - 1)} triangles: radius
     * {@code r * (1 + bump * sin(k theta) sin(k phi))} with k = 9 ripples, normals averaged from
     * the adjacent faces (area-weighted). 256 segments and 200 rings give 101,888 triangles.
     */
    public static MeshData bumpySphere(Vec3 center, double radius, double bump, int segments, int rings) {
        if (segments < 3 || rings < 2) {
            throw new IllegalArgumentException("need at least 3 segments and 2 rings");
        }
        // vertices: the two poles and (rings - 1) rings of `segments` vertices
        int vertices = 2 + (rings - 1) * segments;
        double[] p = new double[3 * vertices];
        int k = 9;
        put(p, 0, center.x(), center.y() + radius, center.z());
        put(p, vertices - 1, center.x(), center.y() - radius, center.z());
        for (int ring = 1; ring < rings; ring++) {
            double theta = Math.PI * ring / rings;
            for (int s = 0; s < segments; s++) {
                double phi = 2 * Math.PI * s / segments;
                double r = radius * (1 + bump * Math.sin(k * theta) * Math.sin(k * phi));
                put(p, vertex(ring, s, segments), center.x() + r * Math.sin(theta) * Math.cos(phi),
                        center.y() + r * Math.cos(theta), center.z() - r * Math.sin(theta) * Math.sin(phi));
            }
        }
        int[] idx = new int[3 * 2 * segments * (rings - 1)];
        int t = 0;
        for (int s = 0; s < segments; s++) {
            int s1 = (s + 1) % segments;
            // top cap
            idx[t++] = 0;
            idx[t++] = vertex(1, s, segments);
            idx[t++] = vertex(1, s1, segments);
            // bands
            for (int ring = 1; ring < rings - 1; ring++) {
                int a = vertex(ring, s, segments), b = vertex(ring, s1, segments);
                int c = vertex(ring + 1, s, segments), d = vertex(ring + 1, s1, segments);
                idx[t++] = a; idx[t++] = c; idx[t++] = d;
                idx[t++] = a; idx[t++] = d; idx[t++] = b;
            }
            // bottom cap
            idx[t++] = vertices - 1;
            idx[t++] = vertex(rings - 1, s1, segments);
            idx[t++] = vertex(rings - 1, s, segments);
        }
        return new MeshData(p, vertexNormals(p, idx), idx);
    }

    private static int vertex(int ring, int segment, int segments) {
        return 1 + (ring - 1) * segments + segment;
    }

    private static void put(double[] a, int i, double x, double y, double z) {
        a[3 * i] = x;
        a[3 * i + 1] = y;
        a[3 * i + 2] = z;
    }

    /** Unit vertex normals: the sum of the adjacent faces' (area-weighted) normals. */
    static double[] vertexNormals(double[] p, int[] idx) {
        double[] n = new double[p.length];
        for (int t = 0; t < idx.length; t += 3) {
            int a = 3 * idx[t], b = 3 * idx[t + 1], c = 3 * idx[t + 2];
            double ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
            double vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
            double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
            for (int v : new int[] {a, b, c}) {
                n[v] += nx;
                n[v + 1] += ny;
                n[v + 2] += nz;
            }
        }
        for (int v = 0; v < n.length; v += 3) {
            double len = Math.sqrt(n[v] * n[v] + n[v + 1] * n[v + 1] + n[v + 2] * n[v + 2]);
            if (len > 0) {
                n[v] /= len;
                n[v + 1] /= len;
                n[v + 2] /= len;
            }
        }
        return n;
    }
}

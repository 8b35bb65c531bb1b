package studio.engine.mesh;

import java.util.Arrays;

import studio.engine.memory.MemoryGate;

/**
 * The triangle corners an OBJ's faces make (each a position index, a normal index and a texture
 * coordinate index, -1 for none), and the mesh they make: vertices are the distinct (position,
 * normal, uv) combinations the corners use, numbered in order of first use, or the positions
 * themselves when no corner needs more.
 */
final class ObjCorners {

    private final MemoryGate memory;
    private int[] cornerPositions;
    private int[] cornerNormals;
    /** Null until the first texture coordinate statement ({@link #trackUvs}). */
    private int[] cornerUvs;
    private int cornerCount;
    private boolean everyCornerHasNormal = true;
    private boolean everyCornerHasUv = true;

    /** Room for {@code triangles} triangles, doubled as needed. */
    ObjCorners(int triangles, MemoryGate memory) {
        this.memory = memory;
        memory.reserve(2 * MemoryGate.ints(3L * triangles));
        cornerPositions = new int[3 * triangles];
        cornerNormals = new int[3 * triangles];
    }

    /** Triangles so far. */
    int triangles() {
        return cornerCount / 3;
    }

    /** From the first {@code vt} on, corners keep a texture coordinate; those before it have none. */
    void trackUvs() {
        if (cornerUvs == null) {
            memory.reserve(MemoryGate.ints(cornerPositions.length));
            cornerUvs = new int[cornerPositions.length];
            Arrays.fill(cornerUvs, 0, cornerCount, -1);
        }
    }

    /** Adds a face's polygon as a fan of triangles around its first corner; -1: no normal or uv. */
    void addFace(int[] positions, int[] normals, int[] uvs, int corners) {
        int triangles = corners - 2;
        if (cornerCount + 3 * triangles > cornerPositions.length) {
            int capacity = Math.max(cornerPositions.length * 2, cornerCount + 3 * triangles);
            memory.reserve((cornerUvs != null ? 3 : 2) * MemoryGate.ints(capacity));
            cornerPositions = Arrays.copyOf(cornerPositions, capacity);
            cornerNormals = Arrays.copyOf(cornerNormals, capacity);
            if (cornerUvs != null) {
                cornerUvs = Arrays.copyOf(cornerUvs, capacity);
            }
        }
        for (int k = 0; k < corners; k++) {
            everyCornerHasNormal &= normals[k] >= 0;
            everyCornerHasUv &= uvs[k] >= 0;
        }
        for (int k = 1; k + 1 < corners; k++) {
            add(positions, normals, uvs, 0);
            add(positions, normals, uvs, k);
            add(positions, normals, uvs, k + 1);
        }
    }

    private void add(int[] positions, int[] normals, int[] uvs, int k) {
        cornerPositions[cornerCount] = positions[k];
        cornerNormals[cornerCount] = normals[k];
        if (cornerUvs != null) {
            cornerUvs[cornerCount] = uvs[k];
        }
        cornerCount++;
    }

    /**
     * The mesh the corners make of the statements' positions, normals and texture coordinates
     * (normals and UVs kept only if every corner names one).
     */
    MeshData mesh(double[] positions, int positionCount, double[] normals, int normalCount, double[] uvs) {
        if (cornerUvs != null && everyCornerHasUv && cornerCount > 0) {
            return withUvs(positions, positionCount, normals, uvs);
        }
        long copies = MemoryGate.doubles(3L * positionCount) + MemoryGate.ints(cornerCount);
        if (!everyCornerHasNormal || cornerCount == 0) {
            memory.reserve(copies);
            return new MeshData(Arrays.copyOf(positions, 3 * positionCount),
                    Arrays.copyOf(cornerPositions, cornerCount), null);
        }
        if (normalCount == positionCount && Arrays.equals(cornerPositions, 0, cornerCount, cornerNormals, 0, cornerCount)) {
            // f v//v ...: normal i belongs to vertex i, as OBJ writers usually arrange it
            memory.reserve(copies + MemoryGate.doubles(3L * normalCount));
            return new MeshData(Arrays.copyOf(positions, 3 * positionCount), Arrays.copyOf(cornerPositions, cornerCount),
                    Arrays.copyOf(normals, 3 * normalCount));
        }
        // Otherwise vertices are (position, normal) pairs, numbered in order of first use.
        LongIntMap pairs = new LongIntMap(positionCount, memory);
        memory.reserve(2 * MemoryGate.doubles(3L * positionCount) + MemoryGate.ints(cornerCount));
        double[] outPositions = new double[3 * positionCount];
        double[] outNormals = new double[3 * positionCount];
        int[] indices = new int[cornerCount];
        int vertices = 0;
        for (int c = 0; c < cornerCount; c++) {
            int p = cornerPositions[c], n = cornerNormals[c];
            long key = ((long) p << 32) | n;
            int v = pairs.get(key);
            if (v < 0) {
                v = vertices++;
                pairs.putNew(key, v);
                if (3 * v + 3 > outPositions.length) {
                    memory.reserve(2 * MemoryGate.doubles(outPositions.length * 2L));
                    outPositions = Arrays.copyOf(outPositions, outPositions.length * 2);
                    outNormals = Arrays.copyOf(outNormals, outNormals.length * 2);
                }
                System.arraycopy(positions, 3 * p, outPositions, 3 * v, 3);
                System.arraycopy(normals, 3 * n, outNormals, 3 * v, 3);
            }
            indices[c] = v;
        }
        memory.reserve(2 * MemoryGate.doubles(3L * vertices));
        return new MeshData(Arrays.copyOf(outPositions, 3 * vertices), indices, Arrays.copyOf(outNormals, 3 * vertices));
    }

    /**
     * The mesh when every corner names a texture coordinate: vertices are (position, normal, uv)
     * triples (normal only if every corner has one), numbered in order of first use.
     */
    private MeshData withUvs(double[] positions, int positionCount, double[] normals, double[] uvs) {
        boolean withNormals = everyCornerHasNormal;
        LongIntMap attributes = new LongIntMap(positionCount, memory); // (normal, uv) -> id
        LongIntMap triples = new LongIntMap(positionCount, memory); // (position, id) -> vertex
        memory.reserve((withNormals ? 2 : 1) * MemoryGate.doubles(3L * positionCount)
                + MemoryGate.doubles(2L * positionCount) + MemoryGate.ints(cornerCount));
        double[] outPositions = new double[3 * positionCount];
        double[] outNormals = withNormals ? new double[3 * positionCount] : null;
        double[] outUvs = new double[2 * positionCount];
        int[] indices = new int[cornerCount];
        int vertices = 0, ids = 0;
        for (int c = 0; c < cornerCount; c++) {
            int p = cornerPositions[c], n = withNormals ? cornerNormals[c] : 0, t = cornerUvs[c];
            long pair = ((long) n << 32) | t;
            int id = attributes.get(pair);
            if (id < 0) {
                id = ids++;
                attributes.putNew(pair, id);
            }
            long key = ((long) p << 32) | id;
            int v = triples.get(key);
            if (v < 0) {
                v = vertices++;
                triples.putNew(key, v);
                if (3 * v + 3 > outPositions.length) {
                    int grown = outPositions.length * 2;
                    memory.reserve((withNormals ? 2 : 1) * MemoryGate.doubles(grown) + MemoryGate.doubles(grown / 3 * 2));
                    outPositions = Arrays.copyOf(outPositions, grown);
                    outUvs = Arrays.copyOf(outUvs, grown / 3 * 2);
                    if (withNormals) {
                        outNormals = Arrays.copyOf(outNormals, grown);
                    }
                }
                System.arraycopy(positions, 3 * p, outPositions, 3 * v, 3);
                if (withNormals) {
                    System.arraycopy(normals, 3 * n, outNormals, 3 * v, 3);
                }
                outUvs[2 * v] = uvs[2 * t];
                outUvs[2 * v + 1] = uvs[2 * t + 1];
            }
            indices[c] = v;
        }
        memory.reserve((withNormals ? 2 : 1) * MemoryGate.doubles(3L * vertices) + MemoryGate.doubles(2L * vertices));
        return new MeshData(Arrays.copyOf(outPositions, 3 * vertices), indices,
                withNormals ? Arrays.copyOf(outNormals, 3 * vertices) : null, Arrays.copyOf(outUvs, 2 * vertices));
    }
}
